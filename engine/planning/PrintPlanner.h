#pragma once
// Planning: the toolpaths of every mesh on every layer become ordered steps per layer — mesh by
// mesh, inner walls, outer walls, skin, infill — with travel, retraction and the fan.
#include <vector>

#include "planning/LayerPlan.h"
#include "settings/Settings.h"
#include "slicing/LayerHeights.h"
#include "toolpaths/MeshToolpaths.h"

namespace mixengine {

struct MeshToolpathsInput {
    const Settings* settings = nullptr;
    std::string name;
    std::vector<MeshLayerGroups> layers;  ///< index = layer
};

PrintPlan planPrint(const std::vector<LayerZ>& heights, const std::vector<MeshToolpathsInput>& meshes,
                    const Settings& global);

/// Fan ratio (0..1) on `layer`: cool_fan_speed_0 on the first layer, ramping to cool_fan_speed_min
/// at cool_fan_full_layer; 0 when cool_fan_enabled is off.
double fanRatioForLayer(const Settings& settings, int layer);

}  // namespace mixengine
