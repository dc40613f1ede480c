#include "gen/model/features/halves_facts.h"

#include <sstream>

#include "gen/model/features/halves.h"
#include "gen/util/number_format.h"

namespace tsf {

nlohmann::json halvesFactsJson(const Scene& s) {
    if (!(s.halves)) return nullptr;
    const SceneHalves& h = *s.halves;
    nlohmann::json holes = nlohmann::json::array();
    for (const auto& [x, y] : holeCentresMm(s)) holes.push_back({x, y});
    return {{"cut_z_mm", s.zMm(h.split_units)},
                   {"slab_mm", {s.zMm(h.slab_bottom_units), s.zMm(h.slab_top_units)}},
                   {"thickness_grown_mm", s.zMm(h.thickness_grown_units)},
                   {"hole_centres_mm", holes},
                   {"hole_diameter_mm", 2 * h.pins.hole_radius_mm},
                   {"hole_depth_mm", s.zMm(h.hole_depth_units)},
                   {"hole_tip_mm", s.zMm(h.hole_apex_units)},
                   {"pin_diameter_mm", 2 * h.pins.pin_radius_mm},
                   {"pin_length_mm", h.pins.pin_length_mm},
                   {"clearance_per_side_mm", kPinClearanceMm}};
}

std::string halvesFactsLines(const Scene& s) {
    if (!(s.halves)) return "";
    std::ostringstream o;
    const SceneHalves& h = *s.halves;
    o << "  halves    cut at z = " << formatFixed(s.zMm(h.split_units), 2) << " mm, the middle of the slab every pillar "
      << "crosses (" << formatFixed(s.zMm(h.slab_bottom_units), 2) << " to " << formatFixed(s.zMm(h.slab_top_units), 2)
      << " mm";
    if (h.thickness_grown_units > 0)
        o << "; the thickness grew by " << formatFixed(s.zMm(h.thickness_grown_units), 2) << " mm to make room for the pins";
    o << ")\n            " << h.hole_centres.size() << " pin holes " << formatFixed(2 * h.pins.hole_radius_mm, 2)
      << " mm across, " << formatFixed(s.zMm(h.hole_apex_units), 2) << " mm deep to the cone's tip, at";
    for (const auto& [x, y] : holeCentresMm(s)) o << " (" << formatFixed(x, 1) << ", " << formatFixed(y, 1) << ")";
    o << " mm; pins " << formatFixed(2 * h.pins.pin_radius_mm, 1) << " mm x " << formatFixed(h.pins.pin_length_mm, 1)
      << " mm, " << formatFixed(kPinClearanceMm, 2) << " mm clearance per side\n";
    return o.str();
}

}  // namespace tsf
