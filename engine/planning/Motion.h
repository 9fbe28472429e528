#pragma once
// Acceleration and jerk per move, as CuraEngine 4.13 sets them when acceleration_enabled /
// jerk_enabled is on: every extrusion takes its feature's value (acceleration_wall_0, _wall_x,
// _topbottom, _infill, _support_infill, _support_roof, _skirt_brim, _prime_tower, _ironing;
// raft_base_acceleration, raft_interface_…, raft_surface_… on the raft; jerk_* alike) from the
// mesh's settings (meshes) or its extruder's (everything else), every travel acceleration_travel /
// jerk_travel of the extruder. Layer 0 uses acceleration_print_layer_0 /
// acceleration_travel_layer_0 (jerk_*_layer_0), and layers 1 … speed_slowdown_layers−1 blend
// linearly towards the feature's value, as speeds do — except skirt, brim and raft, which keep their
// own; layers below the model (negative: raft and filler layers) take every value unblended.
// A value of 0 in a step means "not written" (the switch is off).
#include <vector>

#include "planning/LayerPlan.h"
#include "settings/Settings.h"

namespace mixengine {

struct MotionSources {
    bool acceleration_enabled = false;
    bool jerk_enabled = false;
    std::vector<const Settings*> meshes;  ///< by mesh index (PlanStep::mesh_index)
    const std::vector<Settings>* extruders = nullptr;
};

MotionSources motionSources(const Settings& global, std::vector<const Settings*> meshes,
                            const std::vector<Settings>& extruders);

/// Sets acceleration_mm_s2 / jerk_mm_s on every Travel and Extrude step of the layer. `extruder`
/// is the active extruder when the layer starts.
void assignMotion(PlannedLayer& layer, const MotionSources& sources, int extruder);

}  // namespace mixengine
