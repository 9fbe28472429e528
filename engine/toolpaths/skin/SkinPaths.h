#pragma once
// The lines that fill one layer's skin, as CuraEngine 4.13 prints each skin part (island of the
// skin area), in this order:
//   1. `outline_count` loops (skin_outline_count) in the skin style, the first half a line width
//      less 10 µm inside the part, each further one a line width further in (each simplified before
//      the next is taken, meshfix_maximum_resolution / _deviation); none when the skin
//      pattern is concentric (unless the part has roofing of another pattern above layer 0). The
//      fill area is the innermost loop less half a line width (the whole part when not even the
//      first loop fits);
//   2. roofing: the fill area where it has air above (SkinAreas::roofing) in the roofing pattern,
//      without overlap (the skin already reaches over it);
//   3. skin: the rest of the fill area in the skin pattern, grown by skin_overlap_mm;
//   4. with fill_perimeter_gaps, the gaps a concentric fill leaves (between its loops, and between
//      the first loop and the edge) filled with lines half a wall line wide at the roofing angle.
// A fill is lines of its pattern at line distance = line width (solid); a concentric fill is loops
// one line width apart, the first half a line width (less the overlap) inside its area. With
// `monotonic` (skin_monotonic / roofing_monotonic) a fill's lines are one sequence in monotonic
// order (toolpaths/skin/MonotonicOrder.h, adjacency 1.1 line widths), numbered from 1 within the result.
// Each path is marked with its skin part (numbered from 1) and its stage 1 to 4 above (roofing 2, skin
// 3; ExtrusionPath::skin_part / skin_stage): the planner prints a skin part's paths together, stage by
// stage (planning/order/SkinOrder.h). A fill of lines that is not monotonic, on a layer whose
// top/bottom pattern is lines or zigzag, carries the two points CuraEngine starts it from away from
// the seam (ExtrusionPath::seam_avoiding_starts: the fill area's vertices nearest to two points far
// out from its bounding box's middle, across the lines). Where a loop starts, and the order within
// a stage, is left to the planner.
#include <functional>
#include <optional>
#include <vector>

#include "geometry/Point.h"
#include "toolpaths/core/ExtrusionPath.h"
#include "toolpaths/core/FeatureStyle.h"
#include "toolpaths/infill/InfillPatterns.h"

namespace mixengine {

struct SkinFillParams {
    InfillPattern pattern = InfillPattern::Lines;
    double angle_degrees = 45;
    coord_um overlap_um = 0;
    FeatureStyle style;
    Feature feature = Feature::Skin;  ///< of the fill's lines (Feature::Roofing for the roofing)
    bool monotonic = false;
    double density = 1.0;  ///< lines width / density apart (bridge_skin_density; skin: 1)
    /// connect_skin_polygons: loops side by side joined (toolpaths/infill/PolygonConnect.h)
    bool connect_polygons = false;
    /// A bridge's fill: its paths are marked ExtrusionPath::bridge with this fan.
    std::optional<double> bridge_fan_ratio;
};

struct SkinPathParams {
    int outline_count = 1;
    /// meshfix_maximum_resolution / _deviation: each skin loop simplified before the next is taken, and
    /// a concentric fill's loops once all are taken (0 and 0: kept), as CuraEngine 4.13.
    coord_um simplify_resolution_um = 0;
    coord_um simplify_deviation_um = 0;
    coord_um z_um = 0;
    bool first_layer = false;
    SkinFillParams skin;     ///< the pattern of this layer (top_bottom_pattern_0 on layer 0)
    SkinFillParams roofing;  ///< overlap 0, feature Feature::Roofing
    /// The style of the lines filling a concentric fill's gaps; none without fill_perimeter_gaps.
    std::optional<FeatureStyle> gap_style;
    double gap_angle_degrees = 45;
    /// Bridged skin (toolpaths/skin/BridgeSkin.h): the fill replacing `skin` for a skin part, or none.
    std::function<std::optional<SkinFillParams>(const Paths& part)> bridge;
};

/// The paths of `skin_area` (roofing included) with `roofing_area` the part of it with air above.
std::vector<ExtrusionPath> generateSkinPaths(const Paths& skin_area, const Paths& roofing_area,
                                             const SkinPathParams& params);

/// Lines filling `gaps` (fill_perimeter_gaps), as step 4 above; none without a gap style.
std::vector<ExtrusionPath> perimeterGapLines(const Paths& gaps, const SkinPathParams& params);

}  // namespace mixengine
