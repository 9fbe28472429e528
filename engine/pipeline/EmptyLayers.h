#pragma once
// As CuraEngine: bottom layers on which nothing of the model gets printed (no wall, skin, infill or
// support for any mesh — e.g. a curved bottom whose first cut is thinner than a line) are removed,
// and the print starts with the first printed layer at the first layer's height, so the layer
// count drops. A layer where the slicer left out open pieces of an unclosed mesh counts as
// printed (CuraEngine keeps it).
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
