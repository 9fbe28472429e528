#pragma once
// Cuts a set of facets with one plane and turns the result into outlines (one cut of a layer).
//
// Contract: cut(…) runs cutFacet on the given facets (slicing/FacetPlane.h), stitches the
// segments (slicing/SegmentStitcher.h), builds the outlines (slicing/OutlineBuilder.h) and
// appends what stayed open to `open_polylines`. A PlaneCutter keeps its buffers between cuts and
// is not thread-safe. validateMeshForSlicing checks what the exact arithmetic relies on.
#include <cstdint>
#include <span>
#include <vector>

#include "mesh/Mesh.h"
#include "slicing/FacetPlane.h"
#include "slicing/SegmentStitcher.h"

namespace mixengine {

struct SliceOptions;

/// Throws InputError when a vertex lies beyond ±kMaxSliceCoordinateUm or the mesh has more than
/// 2³¹ − 1 faces, InternalError when a face indexes past the vertices.
void validateMeshForSlicing(const Mesh& mesh);

class PlaneCutter {
  public:
    Paths cut(const Mesh& mesh, std::span<const std::uint32_t> facets, coord_um plane_z, OnPlaneRule rule,
              const SliceOptions& options, Paths& open_polylines);

    /// Segments produced by this cutter so far (for statistics).
    std::size_t segmentCount() const { return segment_count_; }
    /// Loops closed across gaps between open pieces so far (the mesh is not closed there).
    std::size_t gapClosedLoops() const { return gap_closed_loops_; }

  private:
    std::vector<FacetSegment> segments_;
    SegmentStitcher stitcher_;
    std::size_t segment_count_ = 0;
    std::size_t gap_closed_loops_ = 0;
};

}  // namespace mixengine
