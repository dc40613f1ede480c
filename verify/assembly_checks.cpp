// checkAssembly: exact intersection volume of every two parts. See assembly_checks.h.
#include "verify/assembly_checks.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>

#include "gen/geometry/cgal_surface_mesh.h"

namespace tsf {
namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;

bool boxesMeet(const Bounds& a, const Bounds& b) {
    return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y &&
           a.min.z <= b.max.z && b.min.z <= a.max.z;
}

}  // namespace

AssemblyResult checkAssembly(const std::vector<MeshPart>& parts, const std::vector<bool>& solid, size_t max_offenders) {
    const auto t0 = std::chrono::steady_clock::now();
    AssemblyResult r;
    Check c;
    c.id = "parts_overlap";
    c.title = "parts touch, never overlap";
    c.unit = "mm^3";
    c.stage = "assembly";
    std::string broken;
    for (size_t k = 0; k < parts.size(); ++k)
        if (k >= solid.size() || !solid[k]) broken += (broken.empty() ? "" : ", ") + parts[k].name;
    if (!broken.empty()) {
        c.status = CheckStatus::Skipped;
        c.note = "needs every part to be a closed solid; not: " + broken;
    } else {
        std::vector<Bounds> boxes;
        for (const MeshPart& p : parts) boxes.push_back(meshBounds(p.mesh));
        namespace PMP = CGAL::Polygon_mesh_processing;
        for (size_t a = 0; a < parts.size(); ++a)
            for (size_t b = a + 1; b < parts.size(); ++b) {
                if (!boxesMeet(boxes[a], boxes[b])) continue;
                ++r.pairs_tested;
                SurfaceMesh ma = toSurfaceMesh<Kernel>(parts[a].mesh), mb = toSurfaceMesh<Kernel>(parts[b].mesh), out;
                if (!PMP::corefine_and_compute_intersection(ma, mb, out)) {
                    // CGAL could not build the intersection as a 2-manifold: the parts meet in a way a touch cannot.
                    r.overlaps.push_back({a, b, std::numeric_limits<double>::quiet_NaN(), boxes[a].min});
                    continue;
                }
                if (out.number_of_faces() == 0) continue;
                const double v = CGAL::to_double(PMP::volume(out));
                if (!(v > 0)) continue;
                Bounds ob{{1e300, 1e300, 1e300}, {-1e300, -1e300, -1e300}};
                for (const auto vi : out.vertices()) {
                    const auto& p = out.point(vi);
                    const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y()), z = CGAL::to_double(p.z());
                    ob.min = {std::min(ob.min.x, x), std::min(ob.min.y, y), std::min(ob.min.z, z)};
                    ob.max = {std::max(ob.max.x, x), std::max(ob.max.y, y), std::max(ob.max.z, z)};
                }
                r.overlaps.push_back({a, b, v,
                                      {(ob.min.x + ob.max.x) / 2, (ob.min.y + ob.max.y) / 2, (ob.min.z + ob.max.z) / 2}});
            }
        std::sort(r.overlaps.begin(), r.overlaps.end(), [](const PartOverlap& x, const PartOverlap& y) {
            return std::isnan(x.volume_mm3) > std::isnan(y.volume_mm3) || x.volume_mm3 > y.volume_mm3;
        });
        c.count = int64_t(r.overlaps.size());
        c.status = c.count == 0 ? CheckStatus::Pass : CheckStatus::Fail;
        for (const PartOverlap& o : r.overlaps) {
            if (c.worst.size() >= max_offenders) break;
            c.worst.push_back({o.at_mm, o.volume_mm3,
                               parts[o.a].name + " and " + parts[o.b].name +
                                   (std::isnan(o.volume_mm3) ? " cross each other (no exact intersection could be built)"
                                                             : " share " + std::to_string(o.volume_mm3) + " mm^3")});
        }
        c.note = std::to_string(parts.size()) + " parts, " + std::to_string(r.pairs_tested) +
                 " pairs whose boxes meet intersected exactly";
    }
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    c.time_ms = ms;
    r.checks.push_back(std::move(c));
    r.stages.push_back({"assembly", ms});
    return r;
}

}  // namespace tsf
