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
#include <cstddef>
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

// Overhanging walls (toolpaths/walls/OverhangWalls.h), as CuraEngine 4.13's addWall / addWallLine print
// them: a loop starts at the first vertex from its seam that does not overhang (nor lies over a
// bridge's air), and a line of the loop with an overhanging end prints at
// ExtrusionPath::overhang_speed_factor of the loop's speed (on a bridged loop: the ends of the whole
// edge, and that factor replaces the speeding up after a bridge).

/// Whether point `k` of `path` overhangs (false for a path without overhang flags).
bool overhangsAt(const ExtrusionPath& path, std::size_t k);

/// The first point of the closed `path` from `start` on that does not overhang; `start` when all do.
std::size_t firstNonOverhanging(const ExtrusionPath& path, std::size_t start);

/// The speed factor of the line of `path` from point `from` to point `to`: overhang_speed_factor when
/// either end overhangs, else 1.
double overhangSpeedFactor(const ExtrusionPath& path, std::size_t from, std::size_t to);

/// The steps of the closed `wall` (with air_edges and bridge_wall) from vertex `start`, the head at
/// `head` (updated); returns the vertex it started at.
std::size_t emitBridgedWall(const ExtrusionPath& wall, std::size_t start, const TravelParams& params,
                            Point2& head, std::optional<Feature>& feature, BridgeMarks& marks,
                            std::vector<PlanStep>& steps);

}  // namespace mixengine
