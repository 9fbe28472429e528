#pragma once
// Planning: the toolpaths of a mesh group become ordered steps per layer. The layers below the
// model come first (GroupToolpaths::raft: raft and filler layers, with their negative numbers, own
// thickness and — raft layers — own fan, planning/Cooling.h); travel on them combs inside the raft's
// outline grown by 0.1 mm (unless retraction_combing is off), as CuraEngine. On each layer the
// extruders print one after the other, the one already active first (fewest tool changes); each
// extruder prints the skirt/brim (layer 0), the ooze shield, its prime tower rings — when it was
// switched to on the layer, or as the tower's outermost extruder, then (prime_tower_wipe_enabled of
// the extruder left) a travel to the tower's middle — its support, then every mesh in order, each
// mesh's layer part by part in CuraEngine's part order (planning/order/PartOrder.h), each part's inner walls,
// outer walls, skin (skin part by skin part, planning/order/SkinOrder.h), infill, then the mesh's paths
// in no part and its ironing — with travel, retraction and the fan.
// The first switch to an extruder in the print is followed by a Prime step (CuraEngine's prime train).
// Travel combs inside the layer's comb area and goes around the parts through the air with
// travel_avoid_other_parts (planning/TravelAreas.h).
#include <functional>
#include <set>
#include <vector>

#include "planning/LayerPlan.h"
#include "settings/Settings.h"
#include "toolpaths/GroupToolpaths.h"

namespace mixengine {

struct PlannerState {
    Point2 head{0, 0};        ///< where planning goes on from (at the start: layer_start_x/_y)
    int extruder = 0;         ///< the active extruder (carried from group to group)
    std::set<int> primed{0};  ///< extruders primed already (the start code primes the first)
};

/// One PlannedLayer per toolpaths.raft entry, then one per toolpaths.heights entry.
/// retraction_combing "off" (or a layer without outlines) → every long travel retracts.
/// `threads` > 1: the layers' comb areas and free space are made on that many helper threads while
/// the layers are planned in order (the result does not depend on it).
PrintPlan planPrint(const GroupToolpaths& toolpaths, const Settings& global,
                    const std::vector<Settings>& extruders, PlannerState& state, int threads = 1);

/// Called on the planning thread with each layer of the plan being made (`plan.layers[layer]`), in
/// order, as soon as no later planning step changes it. With one extruder and neither coasting nor
/// layer wipes a layer is final once the layer after it is planned; else every layer is handed
/// over when the plan is complete.
using FinalLayer = std::function<void(const PrintPlan& plan, std::size_t layer)>;

/// planPrint() into `plan` (empty at the call), handing each layer to `on_final` once it is final.
/// The layers handed over stay where they are (no reallocation) as long as `plan` lives, also when
/// planning throws, so another thread may read them while later layers are planned.
void planPrint(PrintPlan& plan, const GroupToolpaths& toolpaths, const Settings& global,
               const std::vector<Settings>& extruders, PlannerState& state, int threads,
               const FinalLayer& on_final);

/// The extruders used on `layer`, in print order: `active` first if used, then ascending.
std::vector<int> extruderOrder(const GroupToolpaths& toolpaths, std::size_t layer, int active);

}  // namespace mixengine
