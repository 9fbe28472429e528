#pragma once
// Overhanging walls of a mesh group (wall_overhang_angle < 90; toolpaths/walls/OverhangWalls.h), against
// what CuraEngine 4.13 counts as the layer below a part: the layer parts of every printed mesh on
// it and, with support_enable, the support under the model there — the support layer
// ceil(support_top_distance / layer thickness) + 1 below: its roof when it has one, else its body (for
// layer numbers above 0). The layer's thickness is layer_height on layer 1, the distance to the
// layer below above it. Spiralized prints have none.
#include <vector>

#include "settings/Settings.h"
#include "slicing/LayerHeights.h"
#include "toolpaths/GroupToolpaths.h"
#include "toolpaths/support/SupportAreas.h"

namespace mixengine {

/// Marks the overhanging walls (ExtrusionPath::overhanging) of every mesh of `meshes` (index = layer,
/// as `heights` and `support`) whose settings ask for it; `global` is the group's.
void markOverhangingWallsOfGroup(const Settings& global, const std::vector<LayerZ>& heights,
                                 const std::vector<SupportLayerAreas>& support,
                                 std::vector<MeshToolpaths>& meshes, int threads);

}  // namespace mixengine
