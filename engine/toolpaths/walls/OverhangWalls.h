#pragma once
// Overhanging walls, as CuraEngine 4.13 finds them (wall_overhang_angle < 90, not spiralized): on
// layer i > 0 the overhang mask of a layer is its outline shrunk by half an outer wall line width,
// less the layer below (without what is narrower than an outer wall line) grown by
// 10 µm + w − half an outer wall line width, w = layer thickness × tan(wall_overhang_angle), the
// result grown by 10 µm. A wall vertex on or inside the mask is overhanging
// (ExtrusionPath::overhanging): a wall line with an overhanging end prints at
// wall_overhang_speed_factor of its speed (not on a small feature, which keeps its own factor), and
// a loop starts at the first vertex from its seam that is neither overhanging nor over a bridge's
// air — both planning's (planning/PathOrder.h, planning/BridgeWalls.h).
// What counts as the layer below (every mesh's parts and the support) is the caller's
// (toolpaths/OverhangingWalls.h).
#include <vector>

#include "settings/Settings.h"
#include "toolpaths/core/ExtrusionPath.h"

namespace mixengine {

struct OverhangWallParams {
    bool enabled = false;           ///< wall_overhang_angle < 90 (the caller leaves spiralized prints out)
    double tan_angle = 0;           ///< tan(wall_overhang_angle)
    coord_um outer_width_um = 400;  ///< wall_line_width_0
    double speed_factor = 1;        ///< wall_overhang_speed_factor, as a fraction
    coord_um small_feature_max_um =
        0;  ///< small_feature_max_length (0: none): shorter loops keep their speed
};

OverhangWallParams overhangWallParams(const Settings& s);

/// The overhang mask of `outlines` over `outlines_below` for a layer `thickness_um` thick.
Paths overhangWallMask(const Paths& outlines, const Paths& outlines_below, coord_um thickness_um,
                       const OverhangWallParams& params);

/// Marks the vertices of the closed `walls` on or inside `mask` (ExtrusionPath::overhanging) and
/// gives the walls with any the overhang speed factor; nothing when no vertex is overhanging.
void markOverhangingWalls(std::vector<ExtrusionPath>& walls, const Paths& mask,
                          const OverhangWallParams& params);

}  // namespace mixengine
