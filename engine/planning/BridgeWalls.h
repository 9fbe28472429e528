#pragma once
// Printing a wall loop that crosses air (toolpaths/walls/BridgeWalls.h), as CuraEngine 4.13's
// LayerPlan::addWall / addWallLine print it:
//   - the loop starts at the first vertex from its seam that is not over air;
//   - a bridged edge is printed at bridge_wall_speed with bridge_wall_material_flow and the bridge
//     fan, marked ;TYPE: … ;BRIDGE;
//   - before a bridge the line coasts (flow 0) over the last coast distance =
//     min(V, 100 mm) × (1 − bridge speed·flow / wall speed·flow) × bridge_wall_coast / 40, V the
//     "volume" (µm × flow × speed factor × mm/s) printed since the last bridge (full at the start);
//   - after a bridge, the rest of that same edge speeds up in 1 mm pieces from
//     max(0.5, min(1, bridge speed / wall speed)) (each piece 3/4 closer to full speed, full from
//     0.9 on), extruding 1 / factor more.
#include <vector>

#include "planning/LayerPlan.h"
#include "planning/TravelRoute.h"
#include "toolpaths/core/ExtrusionPath.h"

namespace mixengine {

/// The ;BRIDGE state and the fan a bridge set (−1: the layer's) while a group is ordered.
struct BridgeMarks {
    bool bridge = false;
    double fan = -1;
};

/// A ;TYPE: (with ;BRIDGE when `bridge`) and the fan (a bridge's, or the layer's: −1) when they change.
void markBridge(Feature feature, bool bridge, double fan_ratio, std::optional<Feature>& current,
                BridgeMarks& marks, std::vector<PlanStep>& steps);
/// A SetFan step when the fan ratio (a bridge's, or the layer's: −1) changes.
void markFan(double fan_ratio, BridgeMarks& marks, std::vector<PlanStep>& steps);

/// The steps of the closed `wall` (with air_edges and bridge_wall) from vertex `start`, the head at
/// `head` (updated); returns the vertex it started at.
std::size_t emitBridgedWall(const ExtrusionPath& wall, std::size_t start, const TravelParams& params,
                            Point2& head, std::optional<Feature>& feature, BridgeMarks& marks,
                            std::vector<PlanStep>& steps);

}  // namespace mixengine
