#pragma once
// Bridged walls, as CuraEngine 4.13 finds them (bridge_settings_enabled): on layer i > 0 the mask
// of air under a part is its outline less the layer below (without what is narrower than an outer
// wall line), shrunk by half an outer wall line width and grown back by a whole one (gaps narrower
// than a line width vanish; the mask reaches the wall's centre line). Each wall loop is split where
// its edges enter and leave the mask; an edge inside it is bridged when at least
// bridge_wall_min_length long (else printed as usual). How a bridged loop prints — start on a
// supported vertex, bridge speed/flow/fan, coasting before a bridge (bridge_wall_coast), speeding
// up after it — is planning's (planning/BridgeWalls.h).
#include <vector>

#include "settings/Settings.h"
#include "toolpaths/core/ExtrusionPath.h"

namespace mixengine {

struct BridgeWallParams {
    bool enabled = false;
    coord_um outer_width_um = 400;   ///< wall_line_width_0
    coord_um min_length_um = 5'000;  ///< bridge_wall_min_length
    BridgeWallStyle style;
};

BridgeWallParams bridgeWallParams(const Settings& s);

/// The air mask of `outlines` over `outlines_below`.
Paths bridgeWallMask(const Paths& outlines, const Paths& outlines_below, coord_um outer_width_um);

/// Splits the closed `wall` at `mask` and sets its air_edges and bridge_wall (nothing when it does
/// not cross air).
void markBridgedEdges(ExtrusionPath& wall, const Paths& mask, const BridgeWallParams& params);

/// markBridgedEdges() for every wall of a layer with outlines `outlines` over `outlines_below`.
void markBridgedWalls(std::vector<ExtrusionPath>& walls, const Paths& outlines, const Paths& outlines_below,
                      const BridgeWallParams& params);

}  // namespace mixengine
