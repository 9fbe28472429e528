#pragma once
// The orientation pass's settings (settings/mixengine/orientation.def.json, category
// dual_orientation) and the nozzle offset of a two-extruder machine, plus the pre-slice hook.
//
//   dual_orientation_optimize        bool   run the pass in `slice` before placement
//   dual_orientation_method          enum   sphere | grid
//   dual_orientation_measure         enum   own_part | all_material
//   dual_orientation_objective       enum   flat_face | low_height | low_overhang
//   dual_orientation_resolution      int    voxels along a part's longest side
//   dual_orientation_verify_count    int    sphere minima verified exactly
//   dual_orientation_grid_step       float  grid method step (degrees)
//   support_angle (Cura's)           float  the overhang angle of the free-spin objective
// Keys that are absent keep OrientOptions' defaults; a bad enum value is an InputError naming it.
#include <string>
#include <utility>
#include <vector>

#include "common/Log.h"
#include "orient/Orienter.h"
#include "settings/Settings.h"

namespace mixengine::orient {

OrientOptions optionsFromSettings(const Settings& global);

/// Parsers shared with the command line; throw InputError naming `what` and the value.
Method parseMethod(const std::string& text, const std::string& what);
Measure parseMeasure(const std::string& text, const std::string& what);
Objective parseObjective(const std::string& text, const std::string& what);

/// d = offset of extruder 1 minus extruder 0 (machine_nozzle_offset_x/y), mm. Throws InputError
/// when the machine has fewer than two extruder trains.
Vec3 nozzleOffsetMm(const std::vector<Settings>& extruders);

/// The slice hook: when dual_orientation_optimize is on, rotates the meshes of extruders 0 and 1
/// together about their common centre (lowest point kept) by the pass's best rotation. With only
/// one of the two extruders used it logs that there is nothing to optimise and changes nothing.
void orientForDualNozzle(const std::vector<std::pair<Mesh*, int>>& meshes_by_extruder, const Settings& global,
                         const std::vector<Settings>& extruders, Log& log);

}  // namespace mixengine::orient
