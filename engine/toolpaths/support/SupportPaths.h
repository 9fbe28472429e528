#pragma once
// The lines that print the support areas of one layer (toolpaths/support/SupportAreas.h):
//   body      — support_wall_count loops just inside the area, then support_pattern at
//               support_line_distance (support_initial_layer_line_distance on layer 0) inside
//               them, at support_infill_angles[layer % n] (default 0°: lines along Y),
//               reaching infill_overlap_mm into the walls when there are walls; on layer
//               0, as CuraEngine, one wall more and lines/zigzag become grid; Feature
//               Support, style of the support infill extruder (support_line_width,
//               speed_support_infill, support_material_flow);
//   roof/floor — support_roof_* / support_bottom_* pattern, line distance, angles (none given: as
//               CuraEngine 4.13, 45°/135° in turn, 90° when thinner than two layers, 0° concentric),
//               width, speed and flow; Feature SupportInterface; a roof on layer 0 has one wall and,
//               dense (lines closer than two widths), its lines spread by initial_layer_line_width_factor.
// With gradual_support_infill_steps or support_infill_sparse_thickness the body's infill follows its
// arrangement (toolpaths/infill/InfillLayers.h, as CuraEngine's gradual support and combined support
// layers): inside the walls, the areas printed t layers thick first (laid out as for a line t times
// as wide, so that they keep farther from the edge, and printed at the body's width with t × the
// flow, as CuraEngine 4.13), then the densities from the sparsest: density k of the last L at
// 2^(k+1)·d shifted by 2^k·d for k < L, 2^L·d for L (d = the body's line distance), so that where
// all print the lines are d apart. The cross pattern (support_pattern cross) is the curve of one
// fractal for all layers, the same at every density, as CuraEngine.
#include <vector>

#include "geometry/Point.h"
#include "toolpaths/core/ExtrusionPath.h"
#include "toolpaths/core/FeatureStyle.h"
#include "toolpaths/infill/InfillLayers.h"
#include "toolpaths/infill/InfillPatterns.h"
#include "toolpaths/support/SupportAreas.h"

namespace mixengine {

struct SupportFill {
    InfillPattern pattern = InfillPattern::Lines;
    coord_um line_distance_um = 0;
    double angle_degrees = 0;
    int wall_count = 0;
    /// zigzag's end pieces, as CuraEngine 4.13 (toolpaths/infill/ZigZag.h): always printed, their last lines
    /// only for the body with support_connect_zigzags
    ZigzagEnds zigzag_ends = ZigzagEnds::Open;
    int zag_skip_count = 0;   ///< support_skip_some_zags: its support_zag_skip_count (0 = off)
    coord_um overlap_um = 0;  ///< how far the infill reaches into the walls (infill_overlap_mm)
    FeatureStyle style;
    /// cross: the support's fractal (toolpaths/infill/cross/CrossFill.h), its loops joined
    /// (zig_zaggify_support) and simplified as InfillParams says.
    const CrossFill* cross = nullptr;
    bool connect_lines = false;
    coord_um simplify_resolution_um = 0;
    coord_um simplify_deviation_um = 0;
};

struct SupportLayerFills {
    SupportFill body, roof, floor;
};

/// `arranged`: the body's infill arrangement on this layer (null: the whole inside at one density).
std::vector<ExtrusionPath> supportLayerPaths(const SupportLayerAreas& areas, const SupportLayerFills& fills,
                                             coord_um z_um, const LayerInfill* arranged = nullptr);

}  // namespace mixengine
