#pragma once
// Walls: concentric insets of a layer's outlines (Cura's wall_line_count, wall_line_width_0/_x,
// wall_0_inset).
//
// The outer wall's centre line lies wall_line_width_0 / 2 + wall_0_inset inside the outline; the
// first inner wall lies wall_line_width_0 + wall_line_width_x / 2 inside it (as CuraEngine 4.13:
// the inset moves the outer wall only), each further wall one wall_line_width_x further in. Holes
// get their own loops (clockwise). As CuraEngine 4.13 (WallsComputation), each wall's centre region
// is a plain inset of the previous one, taken part by part: a piece of it narrower than the line
// still gets its loop (the loop overlaps itself there), a part narrower than one line gets none;
// when an inset splits a part into more than three loops more than before (more than four for the
// outer wall), the inset for a line 10 µm narrower is used if it saves more than three loops. Each
// region is simplified (meshfix_maximum_resolution / _deviation) before the next is taken.
#include <vector>

#include "geometry/Point.h"
#include "toolpaths/core/ExtrusionPath.h"

namespace mixengine {

struct WallParams {
    int wall_count = 2;
    coord_um outer_width_um = 400;
    coord_um inner_width_um = 400;
    coord_um outer_inset_um = 0;  ///< wall_0_inset
    double outer_speed_mm_s = 30;
    double inner_speed_mm_s = 60;
    double outer_flow = 1.0;
    double inner_flow = 1.0;
    int outer_extruder = 0;
    int inner_extruder = 0;
    /// Which region the skin of the layers around compares with (toolpaths/skin/Skin.h): 0 = the
    /// outline, k = the centre region of wall k (1 = outer wall).
    int top_reference = 2;
    int bottom_reference = 2;
    /// The region roofing compares with (CuraEngine's min(2, wall count)); −1 = not wanted.
    int roofing_reference = -1;
    /// optimize_wall_printing_order: the loops of each outline (part outline or hole) form one
    /// sequence (ExtrusionPath::sequence, toolpaths/walls/WallOrder.h), its inner loops listed from the
    /// innermost out — or from the outermost in with `outer_first` (outer_inset_first).
    bool group_by_outline = false;
    bool outer_first = false;
    /// fill_perimeter_gaps: find the gaps between consecutive walls (WallResult::perimeter_gaps),
    /// less the pieces under 2 outer wall widths squared with `filter_tiny_gaps`.
    bool perimeter_gaps = false;
    bool filter_tiny_gaps = true;
    /// fill_outline_gaps: find the gaps between the outline and the outer wall (WallResult::outline_gaps,
    /// toolpaths/walls/OutlineGaps.h).
    bool outline_gaps = false;
    /// meshfix_maximum_resolution / _deviation: each wall's centre region is simplified as the
    /// outlines are (slicing/OutlineCleanup.h) before the next wall is inset from it; 0 and 0 = not.
    coord_um simplify_resolution_um = 0;
    coord_um simplify_deviation_um = 0;
};

struct WallResult {
    /// Outer walls first, then the inner ones, wall by wall (with group_by_outline the inner ones
    /// from the innermost wall out, unless outer_first).
    std::vector<ExtrusionPath> walls;
    Paths inner_area;  ///< the area inside the innermost wall (its inner edge); united (Loops::United)
    /// The reference regions asked for in WallParams; a part with fewer walls than the reference
    /// uses its innermost wall's region (as CuraEngine 4.13 takes insets[min(k, count) − 1]).
    /// Always as a Clipper union returns them (Loops::United), the outline (k = 0) included.
    Paths top_reference, bottom_reference;
    Paths roofing_reference;  ///< empty when WallParams::roofing_reference is −1
    /// As CuraEngine 4.13 finds them: wall k's centre region less half its width and 15 µm, less
    /// wall k+1's centre region grown by half its width — where a part lacks wall k+1, all of its
    /// inside (WallParams::perimeter_gaps).
    Paths perimeter_gaps;
    /// The gaps between the outline and the outer wall (WallParams::outline_gaps; OutlineGaps.h).
    Paths outline_gaps;
    /// The outer wall's centre region, simplified (CuraEngine 4.13's insets[0] of every part; parts
    /// too thin for a wall have none); empty without walls.
    Paths outer_region;
    /// The outlines' islands (splitIslands: an outline with its holes each), which the walls are
    /// made part by part from.
    std::vector<Paths> parts;
};

WallResult generateWalls(const Paths& outlines, const WallParams& params);

}  // namespace mixengine
