#pragma once
// As CuraEngine: bottom layers where no mesh has an outline left after clean-up (e.g. a curved
// bottom whose first cut is a loop under minimum_polygon_circumference) and no support is printed
// are removed; the print starts with the first non-empty layer at the first layer's height, so the
// layer count drops; when no layer prints (a flat or floating facet) all are removed. A layer where the
// slicer left out open pieces of an unclosed mesh counts as non-empty (CuraEngine keeps it). Known
// difference: CuraEngine also drops a first layer whose loops are tiny but above that circumference (knot2 at
// 0.2 mm layers on the Ender-3).
#include <cstddef>
#include <vector>

#include "slicing/LayerHeights.h"
#include "slicing/Slicer.h"
#include "toolpaths/GroupToolpaths.h"

namespace mixengine {

std::size_t leadingEmptyLayers(const GroupToolpaths& toolpaths,
                               const std::vector<std::vector<SlicedLayer>>& meshes);

/// Removes the first `count` layers of every per-layer list; heights keep their first entries.
void dropLeadingLayers(std::size_t count, GroupToolpaths& toolpaths, std::vector<LayerZ>& heights,
                       std::vector<Paths>& comb_areas);

}  // namespace mixengine
