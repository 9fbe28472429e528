#pragma once
// Infill patterns by Cura's names, all built from one line distance d (Cura's resolved
// infill_line_distance / support_line_distance / skin spacing, which already carries the pattern's
// multiplier: grid ×2, triangles/trihexagon/cubic ×3, tetrahedral/quarter_cubic ×2), as CuraEngine
// 4.13's Infill class builds them:
//   lines             — one line set at the angle, d apart;
//   zigzag            — the same lines joined along the area's edge (toolpaths/infill/ZigZag.h);
//   grid              — line sets at angle and angle + 90°, each d apart;
//   triangles         — angle, +60°, +120°, each d apart;
//   trihexagon        — as triangles with the third set shifted by d/2;
//   cubic             — angle, +120°, +240°, each d apart, shifted by z/√2 so cubes build up;
//   tetrahedral, quarter_cubic — two directions of line pairs 2d apart, shifted with z;
//   concentric        — loops d apart, the first d − w/2 inside the area (its centre line one line
//                       distance from the edge of a line along the area's edge), each inset from the
//                       one before, then all simplified by simplify_resolution_um / _deviation_um;
//   gyroid            — toolpaths/infill/GyroidInfill.h with period 2.41·d.
//   cubicsubdiv       — the lines of an octree of cubes at this height (toolpaths/infill/SubdivCubes.h, the
//                       caller's subdiv_lines) cut to
//                       the area grown by the overlap (no wall inset, not connected, as CuraEngine);
//                       as cubic without the octree.
//   cross, cross_3d   — the closed curve of the caller's cross fractal (toolpaths/infill/cross/CrossFill.h,
//                       one per mesh or for the support) at this height, with cross_3d's pockets
//                       (pocket_um); connected (zig_zaggify): the area the curve encloses cut to the
//                       area, printed as loops simplified by simplify_resolution_um / _deviation_um
//                       (CuraEngine simplifies its infill polygons so); else the curve cut to the area
//                       and printed segment by segment as separate lines; without a fractal, as lines.
//   lightning         — the trees of lightning infill at this layer (toolpaths/infill/lightning/
//                       LightningInfill.h, the caller's lightning_trees) whose root lies in the area
//                       (or within 5 µm of it), uncut (no overlap, no wall inset, not connected, as
//                       CuraEngine); nothing in an area below w µm² or without trees.
//
// Placement: every line set goes through the pattern origin (origin_um: CuraEngine's infill origin,
// the mesh's middle plus infill_offset_x/_y; its shift across a set at angle a is
// x·cos a − y·sin a, truncated to microns) shifted by shift_um (CuraEngine's infill shift, used by
// gradual infill) and by the pattern's own shift; segments shorter than w/5 are dropped. Concentric
// and gyroid ignore the origin, as CuraEngine.
//
// Around the pattern (Infill::generate):
//   - the lines fill the area grown by overlap_um and shrunk by wall_count·w, and by w/2 more
//     where they are connected (zigzag, or connect_lines: zig_zaggify_infill, for the line-based
//     patterns: toolpaths/infill/ConnectedLines.h; gyroid's lines are not connected);
//   - multiplier N > 1: toolpaths/infill/InfillMultiplier.h, inside the area shrunk by wall_count·w (and
//     w/2 with connect_lines; grown by the overlap for cross and cross_3d, as CuraEngine); for even N
//     the lines are made unconnected and the connections come from the multiplier's cells;
//   - wall_count loops (infill_wall_line_count) w/2, 3w/2, … inside the area, printed as closed fill.
#include <string>
#include <vector>

#include "geometry/Point.h"
#include "geometry/PolygonOps.h"
#include "toolpaths/core/ExtrusionPath.h"
#include "toolpaths/infill/ZigZag.h"
#include "toolpaths/infill/cross/CrossFill.h"
#include "toolpaths/infill/lightning/TreeLines.h"

namespace mixengine {

enum class InfillPattern {
    Lines,
    ZigZag,
    Grid,
    Triangles,
    TriHexagon,
    Cubic,
    CubicSubdiv,
    Tetrahedral,
    QuarterCubic,
    Concentric,
    Gyroid,
    Cross,
    Cross3d,
    Lightning,
};

/// Cura's value → pattern; an unknown value is an InputError naming `key`.
InfillPattern infillPatternOf(const std::string& text, const std::string& key);

struct InfillParams {
    InfillPattern pattern = InfillPattern::Lines;
    coord_um line_distance_um = 0;  ///< 0 = nothing
    double angle_degrees = 45;
    coord_um z_um = 0;  ///< height of the layer (cubic, tetrahedral, gyroid)
    coord_um line_width_um = 400;
    Feature feature = Feature::Fill;
    double speed_mm_s = 60;
    double flow = 1.0;
    int extruder = 0;
    ZigzagEnds zigzag_ends = ZigzagEnds::None;  ///< zigzag: the area's ends (toolpaths/infill/ZigZag.h)
    int zag_skip_count = 0;         ///< zigzag: leave out every n-th connection (toolpaths/infill/ZigZag.h)
    Point2 origin_um{0, 0};         ///< every line set passes through it
    Loops area_loops = Loops::Any;  ///< what is known of the area's loops (geometry/PolygonOps.h)
    coord_um shift_um = 0;          ///< extra shift of every line set across its lines
    coord_um overlap_um = 0;        ///< the lines reach this far beyond the area
    int wall_count = 0;             ///< loops around the area (infill_wall_line_count)
    int multiplier = 1;             ///< parallel lines per line (infill_multiplier)
    bool connect_lines = false;     ///< zig_zaggify_infill
    /// connect_infill_polygons / connect_skin_polygons: the loops (the pattern's, then the walls) joined
    /// where they lie side by side (toolpaths/infill/PolygonConnect.h)
    bool connect_polygons = false;
    const Paths* subdiv_lines = nullptr;  ///< cubicsubdiv: the octree's lines at z_um (the caller's)
    const CrossFill* cross = nullptr;     ///< cross, cross_3d: the fractal (the caller's)
    coord_um pocket_um = 0;               ///< cross_3d: cross_infill_pocket_size (≤ 10: none)
    coord_um simplify_resolution_um =
        0;  ///< cross, concentric: the loops' meshfix_maximum_resolution (0: kept)
    coord_um simplify_deviation_um = 0;  ///< cross, concentric: the loops' meshfix_maximum_deviation
    const std::vector<LightningTreeLines>* lightning_trees =
        nullptr;  ///< lightning: this layer's (the caller's)
};

/// The pattern's lines inside `area` (lines end on its boundary grown by the overlap).
std::vector<ExtrusionPath> generateInfill(const Paths& area, const InfillParams& params);

}  // namespace mixengine
