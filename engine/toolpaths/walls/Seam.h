#pragma once
// Where wall loops start (Cura's z_seam_type, z_seam_x/y, z_seam_relative, z_seam_corner).
//
//   back            — the vertex nearest to (z_seam_x, z_seam_y) — with z_seam_relative taken from the
//                     centre of the mesh's bounding box — with corners of the preferred kind
//                     (z_seam_corner) drawing it: a vertex's squared distance is lessened by a tenth
//                     of itself times how much its corner (measured from its two neighbours) bends
//                     the preferred way, twice for concave corners with "weighted";
//   sharpest_corner — the corner bending most the preferred way (inner = concave, outer = convex,
//                     any, weighted = concave counting twice); corners within 2.5 % of a half turn
//                     tie; with z_seam_corner none as shortest;
//   random          — a vertex drawn from a hash of the layer and the loop's number (reproducible);
//   shortest        — no fixed seam: the planner starts where the head is.
// The search is CuraEngine 4.13's, in its arithmetic (64-bit squared distances, single-precision
// scores) and order: it starts at the vertex nearest to the seam point (for sharpest corner a point far
// behind the plate: the back-most vertex) and goes round once in the loop's order; of vertices scoring
// within 25 µm² the last one met wins, where single precision cannot hold 25 µm² (far from the seam
// point) only a strictly better score. A placed seam rotates the loop so that the seam vertex is
// points.front() and sets ExtrusionPath::fixed_start.
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
};

/// From a mesh's settings; `mesh_centre_um` is the centre of the mesh's XY bounding box.
SeamParams seamParamsFrom(const Settings& s, const Point2& mesh_centre_um);

/// The index of the seam vertex of a closed loop (material on the loop's left, as for outer
/// contours counter-clockwise and holes clockwise; the loop's order and first vertex are the order
/// of the search, as CuraEngine's are). `seed` drives the random type; 0 for shortest and for
/// sharpest corner without a corner preference (placeSeams leaves those to the planner).
std::size_t seamVertex(const Path& loop, const SeamParams& params, std::uint64_t seed);

/// Places the seam of every closed loop in `paths` (loop number = index in `paths`) on `layer`.
void placeSeams(std::vector<ExtrusionPath>& paths, const SeamParams& params, int layer);

}  // namespace mixengine
