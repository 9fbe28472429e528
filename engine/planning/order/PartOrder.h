#pragma once
// A mesh's layer printed part by part, as CuraEngine 4.13 prints its layer parts: each part's
// walls, skin and infill one after the other, the parts in the order CuraEngine's part order gives.
//
// Parts are MeshLayerGroups::parts (disjoint areas). A path belongs to the part that holds the
// first of its points lying in one; a path with no point in any part belongs to none (printed
// after the parts, with the ironing).
//
// Part order of a printed mesh (z seam order): each part is represented by its outer wall loop —
// the largest closed outer wall in the part (CuraEngine's insets[0][0]), else its outline's outer
// contour — and starts at that loop's seam (a loop with fixed_start: points.front()), else at its
// vertex nearest to the seam position (z_seam_type back) or to the head. The search starts at the
// seam position (back) or the head, takes the part whose start is nearest, and goes on from that
// part's start (not from where it ends). Meshes that are not printed as models (infill meshes,
// cutting meshes) take, each time, the part whose loop has a vertex nearest to the head.
#include <cstddef>
#include <optional>
#include <vector>

#include "geometry/Point.h"
#include "toolpaths/MeshToolpaths.h"

namespace mixengine {

struct LayerParts {
    /// [part] the paths of each part, in the groups of `MeshLayerGroups` (no ironing, no parts).
    std::vector<MeshLayerGroups> parts;
    /// The paths in no part and the ironing; comb_area and infill_start as the layer's.
    MeshLayerGroups rest;
    /// [part] the loop the part order is found on (see above), and its start index on it when fixed.
    std::vector<Path> loops;
    std::vector<std::optional<std::size_t>> fixed_starts;
};

/// The paths of `groups` by part. Without parts everything is in `rest`.
LayerParts splitByPart(const MeshLayerGroups& groups);

/// The z seam order of the parts (indices into parts.parts), searched from `seam_position` when
/// set, else from `head`.
std::vector<std::size_t> seamPartOrder(const LayerParts& parts, const std::optional<Point2>& seam_position,
                                       const Point2& head);

/// The part not `done` whose loop has the vertex nearest to `head` (parts.size() when none is left).
std::size_t nearestPart(const LayerParts& parts, const std::vector<bool>& done, const Point2& head);

}  // namespace mixengine
