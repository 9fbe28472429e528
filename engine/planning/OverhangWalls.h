#pragma once
// Printing an overhanging wall loop (toolpaths/walls/OverhangWalls.h), as CuraEngine 4.13's
// LayerPlan::addWall / addWallLine print it: the loop starts at the first vertex from its seam that
// does not overhang (nor lies over a bridge's air: planning/BridgeWalls.h), and a line of the loop
// with an overhanging end prints at ExtrusionPath::overhang_speed_factor of the loop's speed.
#include <cstddef>

#include "toolpaths/core/ExtrusionPath.h"

namespace mixengine {

/// Whether point `k` of `path` overhangs (false for a path without overhang flags).
bool overhangsAt(const ExtrusionPath& path, std::size_t k);

/// The first point of the closed `path` from `start` on that does not overhang; `start` when all do.
std::size_t firstNonOverhanging(const ExtrusionPath& path, std::size_t start);

/// The speed factor of the line of `path` from point `from` to point `to`: overhang_speed_factor when
/// either end overhangs, else 1.
double overhangSpeedFactor(const ExtrusionPath& path, std::size_t from, std::size_t to);

}  // namespace mixengine
