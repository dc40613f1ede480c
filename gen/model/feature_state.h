// FeatureStates: what each feature placed on a Scene (Scene::features), or
// was asked for (SceneParams::requests), held by type, so the
// Scene names no feature (gen/model/feature.h). A feature keeps its own
// data-only record type (the scale's SceneScale, gen/model/scene_scale.h)
// and reads and writes it here; nobody else needs to know it exists.
//
// A Scene is copied by value (buildScene's searches, the tiles): the states
// are copied with it, as the members they replace were.
#pragma once

#include <any>
#include <vector>

namespace tsf {

class FeatureStates {
public:
    /// The state of type T, or null when the feature placed none.
    template <class T>
    const T* get() const {
        for (const std::any& s : states_)
            if (const T* t = std::any_cast<T>(&s)) return t;
        return nullptr;
    }
    template <class T>
    T* get() {
        for (std::any& s : states_)
            if (T* t = std::any_cast<T>(&s)) return t;
        return nullptr;
    }
    /// Sets (or replaces) the state of type T.
    template <class T>
    T& set(T state) {
        if (T* t = get<T>()) return *t = std::move(state);
        return *std::any_cast<T>(&states_.emplace_back(std::move(state)));
    }
    /// Removes the state of type T (none: nothing).
    template <class T>
    void reset() {
        for (auto it = states_.begin(); it != states_.end(); ++it)
            if (std::any_cast<T>(&*it)) {
                states_.erase(it);
                return;
            }
    }

private:
    std::vector<std::any> states_;
};

}  // namespace tsf
