// Which faces of a constrained triangulation lie inside its constraint loops.
//
// Floods from the infinite face and counts the constraints crossed on the way
// to each face. With closed constraint loops the parity of that count is the
// same on every path, so after the call info() % 2 == 1 exactly for the faces
// inside an odd number of loops (inside a polygon and outside its holes).
// Used by the direct mesher (the flat bottom inside the rim) and by the
// orientation marks (the flat region around the triangle). The face base must
// carry an int info() (Triangulation_face_base_with_info_2).
#pragma once

#include <utility>
#include <vector>

namespace tsf {

template <class Cdt>
void markInsideByParity(Cdt& cdt) {
    for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = -1;
    std::vector<std::pair<typename Cdt::Face_handle, int>> stack{{cdt.infinite_face(), 0}};
    while (!stack.empty()) {
        auto [f, crossed] = stack.back();
        stack.pop_back();
        if (f->info() != -1) continue;
        f->info() = crossed;
        for (int e = 0; e < 3; ++e) {
            const typename Cdt::Face_handle nb = f->neighbor(e);
            if (nb->info() == -1) stack.push_back({nb, cdt.is_constrained({f, e}) ? crossed + 1 : crossed});
        }
    }
}

}  // namespace tsf
