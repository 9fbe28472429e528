#pragma once
// Coasting, as CuraEngine 4.13 writes it (coasting_enable of the extruder that prints): the end of
// an extrusion path that is followed by a travel is not extruded but travelled over, so the pressure
// left in the nozzle lays down the last bit of the line.
//   - a path is a run of consecutive Extrude steps of one feature with the same speed, line width
//     and volume per length (CuraEngine's GCodePath); it coasts when the next move — in this layer
//     or, for the layer's last path, the next layer's first — is a travel;
//   - the coasted distance is coasting_volume / (layer thickness × line width); a path shorter than
//     (coasting_min_volume + coasting_volume) / (thickness × width) coasts that distance scaled by
//     its length over the longer one; nothing under 0.1 mm of path or under 1 µm of coasting;
//   - the path is extruded up to the coasting start, then travelled (no retraction) to its end at
//     coasting_speed × the path's speed, keeping the print acceleration and jerk.
// Distances in whole microns as CuraEngine computes them. Applied after cooling (speeds are final).
#include <vector>

#include "planning/LayerPlan.h"
#include "settings/Settings.h"

namespace mixengine {

struct CoastingParams {
    bool enabled = false;
    double volume_mm3 = 0.064;    ///< coasting_volume
    double min_volume_mm3 = 0.8;  ///< coasting_min_volume
    double speed_ratio = 0.9;     ///< coasting_speed
};

/// The coasting of one extruder train.
CoastingParams coastingParams(const Settings& extruder);

/// Applies coasting to every layer of `plan`; `per_extruder[e]` is train e's coasting, `extruder` the
/// active extruder when the plan starts.
void applyCoasting(PrintPlan& plan, const std::vector<CoastingParams>& per_extruder, int extruder);

}  // namespace mixengine
