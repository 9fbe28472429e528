#pragma once
// Where wall loops start (Cura's z_seam_type, z_seam_x/y, z_seam_relative, z_seam_corner).
//
//   back            — the vertex nearest to (z_seam_x, z_seam_y), corners of the preferred kind
//                     (z_seam_corner) drawing it as CuraEngine 4.13 does: a vertex's squared
//                     distance is lessened by a tenth of itself times how much its corner (measured
//                     from its two neighbours) bends the preferred way — twice for concave corners
//                     with "weighted"; with z_seam_relative the point is taken relative to the centre
//                     of the mesh's bounding box;
//   sharpest_corner — the sharpest corner of the preferred kind (z_seam_corner: inner = concave,
//                     outer = convex, any, weighted = concave first); the turn at a vertex is
//                     measured between points `corner_lookaround_um` before and after it, so a
//                     finely divided round corner counts as a corner;
//   random          — a vertex drawn from a hash of the layer and the loop's number (reproducible);
//   shortest        — no fixed seam: the planner starts where the head is.
// Near-ties (a circle, the corners of a square) go to the back-most vertex (largest Y, then
// largest X), which is where CuraEngine puts them too. A placed seam rotates the loop so that the
// seam vertex is points.front() and sets ExtrusionPath::fixed_start.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "geometry/Point.h"
#include "settings/Settings.h"
#include "toolpaths/core/ExtrusionPath.h"

namespace mixengine {

enum class SeamType { Back, Shortest, Random, SharpestCorner };
enum class SeamCorner { None, Inner, Outer, Any, Weighted };

struct SeamParams {
    SeamType type = SeamType::SharpestCorner;
    SeamCorner corner = SeamCorner::Inner;
    Point2 position_um{0, 0};  ///< absolute (z_seam_relative already applied)
    coord_um corner_lookaround_um = 400;
};

/// From a mesh's settings; `mesh_centre_um` is the centre of the mesh's XY bounding box.
SeamParams seamParamsFrom(const Settings& s, const Point2& mesh_centre_um);

/// The index of the seam vertex of a closed loop (material on the loop's left, as for outer
/// contours counter-clockwise and holes clockwise). `seed` drives the random type.
std::size_t seamVertex(const Path& loop, const SeamParams& params, std::uint64_t seed);

/// Places the seam of every closed loop in `paths` (loop number = index in `paths`) on `layer`.
void placeSeams(std::vector<ExtrusionPath>& paths, const SeamParams& params, int layer);

}  // namespace mixengine
