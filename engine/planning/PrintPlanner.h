#pragma once
// Planning: the toolpaths of a mesh group become ordered steps per layer. On each layer the
// extruders print one after the other, the one already active first (fewest tool changes); each
// extruder prints its prime tower and ooze shield, the skirt/brim (layer 0), its support, then
// every mesh in order — inner walls, outer walls, skin, infill — with travel, retraction and the fan.
// Travel combs inside the layer's comb area (combArea: per mesh by its retraction_combing mode),
// even-odd (planning/CombBoundary.h), and goes around the parts through the air with
// travel_avoid_other_parts (freeSpace; planning/TravelRoute.h).
#include <vector>

#include "planning/LayerPlan.h"
#include "settings/Settings.h"
#include "toolpaths/GroupToolpaths.h"

namespace mixengine {

struct PlannerState {
    Point2 head{0, 0};
    int extruder = 0;  ///< the active extruder (carried from group to group)
};

/// One PlannedLayer per toolpaths.heights entry. retraction_combing "off" (or a layer without
/// outlines) → every long travel retracts.
PrintPlan planPrint(const GroupToolpaths& toolpaths, const Settings& global,
                    const std::vector<Settings>& extruders, PlannerState& state);

/// The outlines of every mesh's sliced layer toolpaths.first_sliced_layer + layer, one after the
/// other (microns).
Paths partOutlines(const GroupToolpaths& toolpaths, std::size_t layer);

/// Where travel on `layer` of `toolpaths` may go without retraction: every mesh's comb area for its
/// retraction_combing mode (MeshLayerGroups::comb_area), or its sliced outlines ("all").
Paths combArea(const GroupToolpaths& toolpaths, std::size_t layer);

/// The space through-air travel may use with travel_avoid_other_parts: a rectangle 5 mm around the
/// parts, less the parts grown (round) by `avoid_distance_um`, as even-odd loops (rectangle first).
Paths freeSpace(const Paths& outlines, coord_um avoid_distance_um);

/// The extruders used on `layer`, in print order: `active` first if used, then ascending.
std::vector<int> extruderOrder(const GroupToolpaths& toolpaths, std::size_t layer, int active);

}  // namespace mixengine
