#include "orient/ExactSolid.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <vector>

namespace mixengine::orient {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;
namespace PMP = CGAL::Polygon_mesh_processing;

struct BoxMm {
    Vec3 min, max;
    bool overlaps(const BoxMm& o, const Vec3& shift) const {
        return min.x < o.max.x + shift.x && o.min.x + shift.x < max.x && min.y < o.max.y + shift.y &&
               o.min.y + shift.y < max.y && min.z < o.max.z + shift.z && o.min.z + shift.z < max.z;
    }
};

/// Builds the surface mesh; false when a face cannot be added (non-manifold configuration).
bool buildSurface(const Mesh& mesh, SurfaceMesh& out) {
    std::vector<SurfaceMesh::Vertex_index> index;
    index.reserve(mesh.vertices.size());
    for (const Point3& p : mesh.vertices)
        index.push_back(out.add_vertex(Point(micronsToMm(p.x), micronsToMm(p.y), micronsToMm(p.z))));
    for (const Face& f : mesh.faces) {
        if (out.add_face(index[f.v[0]], index[f.v[1]], index[f.v[2]]) == SurfaceMesh::null_face())
            return false;
    }
    return true;
}

}  // namespace

struct ExactSolid::Impl {
    SurfaceMesh surface;
    BoxMm box;
    double volume = 0;
};

std::string describe(SolidStatus status) {
    switch (status) {
        case SolidStatus::Exact:
            return "closed";
        case SolidStatus::Open:
            return "open (has boundary edges)";
        case SolidStatus::NonManifold:
            return "non-manifold";
        case SolidStatus::SelfIntersecting:
            return "self-intersecting";
    }
    return "unknown";
}

ExactSolid::ExactSolid(const Mesh& mesh) : impl_(std::make_unique<Impl>()) {
    const AABB3 b = mesh.bounds();
    impl_->box = {{micronsToMm(b.min.x), micronsToMm(b.min.y), micronsToMm(b.min.z)},
                  {micronsToMm(b.max.x), micronsToMm(b.max.y), micronsToMm(b.max.z)}};
    if (!buildSurface(mesh, impl_->surface)) {
        status_ = SolidStatus::NonManifold;
        return;
    }
    if (!CGAL::is_closed(impl_->surface)) {
        status_ = SolidStatus::Open;
        return;
    }
    if (PMP::does_self_intersect(impl_->surface)) {
        status_ = SolidStatus::SelfIntersecting;
        return;
    }
    if (!PMP::does_bound_a_volume(impl_->surface))
        PMP::orient_to_bound_a_volume(impl_->surface);
    impl_->volume = CGAL::to_double(PMP::volume(impl_->surface));
    if (impl_->volume < 0) {  // consistently wound, but inside out
        PMP::reverse_face_orientations(impl_->surface);
        impl_->volume = -impl_->volume;
    }
    status_ = SolidStatus::Exact;
}

ExactSolid::~ExactSolid() = default;

double ExactSolid::volumeMm3() const {
    return impl_->volume;
}

std::optional<double> ExactSolid::intersectionVolumeMm3(const ExactSolid& other, const Vec3& shift_mm) const {
    if (!exact() || !other.exact())
        return std::nullopt;
    if (!impl_->box.overlaps(other.impl_->box, shift_mm))
        return 0.0;
    SurfaceMesh mine = impl_->surface;
    SurfaceMesh moved = other.impl_->surface;
    const Kernel::Vector_3 t(shift_mm.x, shift_mm.y, shift_mm.z);
    for (const auto v : moved.vertices())
        moved.point(v) = moved.point(v) + t;
    SurfaceMesh result;
    try {
        if (!PMP::corefine_and_compute_intersection(mine, moved, result))
            return std::nullopt;
    } catch (const std::exception&) {
        return std::nullopt;
    }
    if (result.number_of_faces() == 0)
        return 0.0;
    return CGAL::to_double(PMP::volume(result));
}

}  // namespace mixengine::orient
