#pragma once
// As CuraEngine: bottom layers where no mesh prints anything (no outline left after clean-up, e.g. a
// curved bottom whose first cut is a loop under minimum_polygon_circumference, or only parts too thin for
// a wall, which CuraEngine drops before it counts the empty first layers) and no support is printed are
// removed; the print starts with the first non-empty layer at the first layer's height, so the layer
// count drops; when no layer prints (a flat or floating facet) all are removed. A layer where the slicer
// left out open pieces of an unclosed mesh counts as non-empty (CuraEngine keeps it).
//
// Part of the toolpath stage: generateGroupToolpaths (toolpaths/GroupToolpaths.h) drops them last.
#include <cstddef>
#include <vector>

#include "toolpaths/GroupToolpaths.h"

namespace mixengine {

/// The number of empty layers at the bottom of `toolpaths` made from `input` (all of them when
/// nothing prints).
std::size_t leadingEmptyLayers(const GroupToolpaths& toolpaths, const ToolpathInput& input);

/// Removes the first `count` layers of every per-layer list of `toolpaths`; toolpaths.heights
/// keeps its first entries (the print starts at the first layer's height) and
/// toolpaths.first_sliced_layer grows by `count`.
void dropLeadingLayers(std::size_t count, GroupToolpaths& toolpaths);

}  // namespace mixengine
