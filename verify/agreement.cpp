// compareMeshes: CGAL bounded-error Hausdorff distance and volumes. See agreement.h.
//
// CGAL 5.5's bounded_error_Hausdorff_distance asserts that every subdivided
// triangle found a face realising its lower bound, which does not hold when
// that bound ties the parent triangle's upper bound (common between
// axis-aligned faces); the distance it returns is right, the debug assertion
// is not (later CGAL versions initialise the bound differently). Assertions
// are off in this file only, and its meshes use a kernel (Simple_cartesian)
// no other file of the verifier instantiates, so no checked template is
// shared with it.
#define CGAL_NO_ASSERTIONS

#include "verify/agreement.h"

#include <array>
#include <chrono>
#include <cmath>
#include <iterator>
#include <vector>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>

#include "verify/detail/format.h"

namespace tsf {
namespace {

using K = CGAL::Simple_cartesian<double>;
using SM = CGAL::Surface_mesh<K::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;
using detail::fmtNum;
using detail::fmtPoint;

double msSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// Surface_mesh of the mesh's usable triangles; `repaired` tells whether
// orient_polygon_soup had to change the soup first.
SM toSurfaceMesh(const Mesh& mesh, bool& repaired) {
    std::vector<K::Point_3> points;
    points.reserve(mesh.positions.size());
    for (const Vec3& p : mesh.positions) points.emplace_back(p.x, p.y, p.z);
    std::vector<std::array<size_t, 3>> polygons;
    polygons.reserve(mesh.triangles.size());
    const size_t n = mesh.positions.size();
    for (const auto& t : mesh.triangles) {
        if (t[0] >= n || t[1] >= n || t[2] >= n || t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue;
        polygons.push_back({t[0], t[1], t[2]});
    }
    repaired = !PMP::is_polygon_soup_a_polygon_mesh(polygons);
    if (repaired) PMP::orient_polygon_soup(points, polygons);
    SM sm;
    PMP::polygon_soup_to_polygon_mesh(points, polygons, sm);
    return sm;
}

Vec3 faceCentroid(const SM& sm, SM::Face_index f) {
    Vec3 c;
    int n = 0;
    for (SM::Vertex_index v : CGAL::vertices_around_face(sm.halfedge(f), sm)) {
        const K::Point_3& p = sm.point(v);
        c = {c.x + p.x(), c.y + p.y(), c.z + p.z()};
        ++n;
    }
    return n ? Vec3{c.x / n, c.y / n, c.z / n} : c;
}

bool finiteMesh(const Mesh& m) {
    for (const Vec3& p : m.positions)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return false;
    return true;
}

}  // namespace

AgreementResult compareMeshes(const Mesh& model, const Mesh& reference, const std::string& reference_name,
                              const AgreementOptions& options) {
    AgreementResult r;
    AgreementFigures& f = r.figures;
    f.reference = reference_name;
    f.reference_triangles = reference.triangleCount();
    f.distance_tolerance_mm = options.distance_tolerance_mm;
    f.hausdorff_error_bound_mm = options.error_bound_mm > 0 ? options.error_bound_mm
                                                           : options.distance_tolerance_mm * kHausdorffBoundFraction;
    f.volume_mm3 = signedVolume(model);
    f.reference_volume_mm3 = signedVolume(reference);
    f.volume_difference_mm3 = f.volume_mm3 - f.reference_volume_mm3;
    f.hausdorff_to_reference_mm = f.hausdorff_from_reference_mm = NAN;

    Check dist;
    dist.id = "reference_distance";
    dist.title = "same surface as the reference (Hausdorff distance)";
    dist.unit = "mm";
    Check vol;
    vol.id = "reference_volume";
    vol.title = "same volume as the reference";
    vol.unit = "mm^3";

    auto t0 = std::chrono::steady_clock::now();
    SM a, b;
    bool a_repaired = false, b_repaired = false;
    const bool usable = finiteMesh(model) && finiteMesh(reference);
    if (usable) {
        a = toSurfaceMesh(model, a_repaired);
        b = toSurfaceMesh(reference, b_repaired);
    }
    if (!usable || a.number_of_faces() == 0 || b.number_of_faces() == 0) {
        dist.status = vol.status = CheckStatus::Fail;
        dist.count = vol.count = 1;
        dist.note = vol.note = usable ? "one of the meshes has no triangles" : "non-finite coordinates";
        r.checks = {dist, vol};
        return r;
    }

    // Area of the model, for the volume tolerance.

    const double area = CGAL::to_double(PMP::area(a));
    f.volume_tolerance_mm3 = area * options.distance_tolerance_mm;
    const Stage build{"reference_mesh", msSince(t0)};
    r.stages.push_back(build);

    t0 = std::chrono::steady_clock::now();
    std::vector<std::pair<SM::Face_index, SM::Face_index>> realizing_ab, realizing_ba;
    f.hausdorff_to_reference_mm = PMP::bounded_error_Hausdorff_distance<CGAL::Sequential_tag>(
        a, b, f.hausdorff_error_bound_mm,
        CGAL::parameters::output_iterator(std::back_inserter(realizing_ab)));
    f.hausdorff_from_reference_mm = PMP::bounded_error_Hausdorff_distance<CGAL::Sequential_tag>(
        b, a, f.hausdorff_error_bound_mm,
        CGAL::parameters::output_iterator(std::back_inserter(realizing_ba)));
    const Stage haus{"hausdorff", msSince(t0)};
    r.stages.push_back(haus);

    dist.stage = haus.name;
    dist.time_ms = haus.time_ms;
    const double bound = f.hausdorff_error_bound_mm;
    const bool to_ok = f.hausdorff_to_reference_mm + bound <= f.distance_tolerance_mm;
    const bool from_ok = f.hausdorff_from_reference_mm + bound <= f.distance_tolerance_mm;
    dist.count = int64_t(!to_ok) + int64_t(!from_ok);
    dist.status = dist.count ? CheckStatus::Fail : CheckStatus::Pass;
    if (!to_ok && !realizing_ab.empty())
        dist.worst.push_back({faceCentroid(a, realizing_ab.front().first), f.hausdorff_to_reference_mm,
                              "this model is " + fmtNum(f.hausdorff_to_reference_mm) +
                                  " mm from the reference near its triangle centred at " +
                                  fmtPoint(faceCentroid(a, realizing_ab.front().first))});
    if (!from_ok && !realizing_ba.empty())
        dist.worst.push_back({faceCentroid(b, realizing_ba.front().first), f.hausdorff_from_reference_mm,
                              "the reference is " + fmtNum(f.hausdorff_from_reference_mm) +
                                  " mm from this model near its triangle centred at " +
                                  fmtPoint(faceCentroid(b, realizing_ba.front().first))});
    dist.note = "to reference " + fmtNum(f.hausdorff_to_reference_mm) + " mm, from reference " +
                fmtNum(f.hausdorff_from_reference_mm) + " mm (+-" + fmtNum(bound) + "), tolerance " +
                fmtNum(f.distance_tolerance_mm) + " mm";
    if (a_repaired || b_repaired)
        dist.note += std::string("; ") + (a_repaired ? "this model" : "the reference") +
                     (a_repaired && b_repaired ? " and the reference" : "") + " re-oriented on a copy first";

    vol.stage = build.name;
    vol.time_ms = build.time_ms;
    vol.count = std::fabs(f.volume_difference_mm3) <= f.volume_tolerance_mm3 ? 0 : 1;
    vol.status = vol.count ? CheckStatus::Fail : CheckStatus::Pass;
    vol.note = "volume " + fmtNum(f.volume_mm3) + " vs " + fmtNum(f.reference_volume_mm3) + " mm^3 (difference " +
               fmtNum(f.volume_difference_mm3) + ", tolerance " + fmtNum(f.volume_tolerance_mm3) + ")";
    if (vol.count) vol.worst.push_back({Vec3{NAN, NAN, NAN}, f.volume_difference_mm3, vol.note});
    r.checks = {dist, vol};
    return r;
}

}  // namespace tsf
