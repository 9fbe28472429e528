#pragma once
// The lines that print the support areas of one layer (toolpaths/support/SupportAreas.h):
//   body      — support_wall_count loops just inside the area, then support_pattern at
//               support_line_distance (support_initial_layer_line_distance on layer 0) inside
//               them, at support_infill_angles[layer % n] (default 0°: lines along Y),
//               reaching infill_overlap_mm into the walls when there are walls; on layer
//               0, as CuraEngine, one wall more and lines/zigzag become grid; Feature
//               Support, style of the support infill extruder (support_line_width,
//               speed_support_infill, support_material_flow);
//   roof/floor — support_roof_* / support_bottom_* pattern, line distance, angles (default 90°),
//               width, speed and flow; Feature SupportInterface (the floor SupportBottom, marked
//               as interface, printed with its own acceleration and jerk as CuraEngine's).
// With gradual_support_infill_steps or support_infill_sparse_thickness the body's infill follows its
// arrangement (toolpaths/infill/InfillLayers.h, as CuraEngine's gradual support and combined support
// layers): inside the walls, the areas printed t layers thick first (laid out as for a line t times
// as wide, so that they keep farther from the edge, and printed at the body's width with t × the
// flow, as CuraEngine 4.13), then the densities from the sparsest: density k of the last L at
// 2^(k+1)·d shifted by 2^k·d for k < L, 2^L·d for L (d = the body's line distance), so that where
// all print the lines are d apart.
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
    bool connect_zigzags = false;  ///< support_connect_zigzags: zigzag with its end pieces
    int zag_skip_count = 0;        ///< support_skip_some_zags: its support_zag_skip_count (0 = off)
    bool connect_lines = false;    ///< zig_zaggify_support: the lines joined along the area's edge
    coord_um overlap_um = 0;       ///< how far the infill reaches into the walls (infill_overlap_mm)
    FeatureStyle style;
};

struct SupportLayerFills {
    SupportFill body, roof, floor;
};

/// `arranged`: the body's infill arrangement on this layer (null: the whole inside at one density).
std::vector<ExtrusionPath> supportLayerPaths(const SupportLayerAreas& areas, const SupportLayerFills& fills,
                                             coord_um z_um, const LayerInfill* arranged = nullptr);

}  // namespace mixengine
