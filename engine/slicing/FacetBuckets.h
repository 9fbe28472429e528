#pragma once
// Which facets can touch which cutting plane, so that no facet is tested against every plane.
//
// Contract: for planes at ascending heights (equal heights allowed), facetsAt(p) lists, in
// increasing order, every facet whose z-range [min z, max z] contains plane p's height; only
// these can yield a segment there. Built with two passes over the facets (a binary search for the
// first and last plane of each facet, then a counting sort into one flat array), so the cost is
// O(facets · log planes + entries) with entries = Σ planes spanned, about the number of segments.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "mesh/Mesh.h"

namespace mixengine {

class FacetBuckets {
  public:
    /// Throws InternalError when the heights are not ascending.
    FacetBuckets(const Mesh& mesh, const std::vector<coord_um>& plane_z_ascending);

    std::span<const std::uint32_t> facetsAt(std::size_t plane) const {
        return {facets_.data() + offsets_[plane], offsets_[plane + 1] - offsets_[plane]};
    }
    std::size_t planeCount() const { return offsets_.size() - 1; }
    std::size_t entryCount() const { return facets_.size(); }

  private:
    std::vector<std::size_t> offsets_;  ///< planeCount() + 1 offsets into facets_
    std::vector<std::uint32_t> facets_;
};

}  // namespace mixengine
