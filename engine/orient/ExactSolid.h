#pragma once
// Exact volumes with CGAL (the only CGAL translation unit of the engine; CGAL stays behind this
// pimpl so that nothing else compiles its headers).
//
// An ExactSolid is a closed, oriented, non-self-intersecting triangle mesh in millimetres.
// Construction checks the mesh: when it is open, non-manifold or self-intersecting, status() says
// which and no exact volume can be computed (the orientation pass then uses the voxel measure).
// Intersections use Polygon_mesh_processing::corefine_and_compute_intersection on copies (with
// exact predicates, Epick kernel) and PMP::volume.
#include <memory>
#include <optional>
#include <string>

#include "geometry/Point.h"
#include "mesh/Mesh.h"

namespace mixengine::orient {

enum class SolidStatus { Exact, Open, NonManifold, SelfIntersecting };

/// "closed", "open (has boundary edges)", ...
std::string describe(SolidStatus status);

class ExactSolid {
  public:
    explicit ExactSolid(const Mesh& mesh);
    ~ExactSolid();
    ExactSolid(const ExactSolid&) = delete;
    ExactSolid& operator=(const ExactSolid&) = delete;

    SolidStatus status() const { return status_; }
    bool exact() const { return status_ == SolidStatus::Exact; }
    /// The enclosed volume (mm³); valid when exact().
    double volumeMm3() const;
    /// vol(this ∩ (other + shift)) in mm³; nullopt when either solid is not exact or CGAL failed.
    std::optional<double> intersectionVolumeMm3(const ExactSolid& other, const Vec3& shift_mm) const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    SolidStatus status_ = SolidStatus::Open;
};

}  // namespace mixengine::orient
