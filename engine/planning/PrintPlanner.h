#pragma once
// Planning: the toolpaths of a mesh group become ordered steps per layer. On each layer the
// extruders print one after the other, the one already active first (fewest tool changes); each
// extruder prints its prime tower and ooze shield, the skirt/brim (layer 0), its support, then
// every mesh in order — inner walls, outer walls, skin, infill — with travel, retraction and the fan.
#include <vector>

#include "planning/LayerPlan.h"
#include "settings/Settings.h"
#include "slicing/LayerHeights.h"
#include "toolpaths/GroupToolpaths.h"

namespace mixengine {

struct PlannerState {
    Point2 head{0, 0};
    int extruder = 0;  ///< the active extruder (carried from group to group)
};

/// `comb_areas[layer]`: where travel may go without retraction (the layer's outlines); empty or
/// retraction_combing "off" → every long travel retracts.
PrintPlan planPrint(const std::vector<LayerZ>& heights, const GroupToolpaths& toolpaths,
                    const Settings& global, const std::vector<Settings>& extruders,
                    const std::vector<Paths>& comb_areas, PlannerState& state);

/// The extruders used on `layer`, in print order: `active` first if used, then ascending.
std::vector<int> extruderOrder(const GroupToolpaths& toolpaths, std::size_t layer, int active);

}  // namespace mixengine
