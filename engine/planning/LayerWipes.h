#pragma once
// Where the wipe script between layers goes, as CuraEngine 4.13 decides (clean_between_layers of the
// extruder): at the start of a layer whose first extruder is the one already active, when that
// extruder has extruded more than max_extrusion_before_wipe (mm³ of lines, coasting included, primes
// not) since its last wipe or since it was last switched to. The script (a WipeScript step, written
// by gcode/WipeScript.h) comes before everything else on the layer and takes the place of the
// retract_at_layer_change retraction. Applied after coasting, so the volumes are the written ones.
#include <vector>

#include "planning/LayerPlan.h"
#include "settings/Settings.h"

namespace mixengine {

struct LayerWipeParams {
    bool enabled = false;             ///< clean_between_layers
    double max_extrusion_mm3 = 10.0;  ///< max_extrusion_before_wipe
};

LayerWipeParams layerWipeParams(const Settings& extruder);

/// Inserts the WipeScript steps into `plan`; `per_extruder[e]` is train e's, `extruder` the active one
/// when the plan starts.
void planLayerWipes(PrintPlan& plan, const std::vector<LayerWipeParams>& per_extruder, int extruder);

}  // namespace mixengine
