#pragma once
// The skirt or brim lines of the other extruders (CuraEngine 4.13's SkirtBrim, "other extruders'
// brim/skirt"): every extruder used in the group other than the adhesion extruder gets lines just
// outside the adhesion extruder's outermost skirt or brim line, one after the other (the first
// half a line width of each apart), each extruder as many as it takes to reach its own
// skirt_brim_minimal_length (none when that is 0). They prime the extruder on layer 0 when it is
// switched to. Width skirt_brim_line_width × initial_layer_line_width_factor, speed
// skirt_brim_speed, flow skirt_brim_material_flow × material_flow_layer_0 of the extruder's train;
// Feature Skirt.
#include <set>
#include <vector>

#include "settings/Settings.h"
#include "toolpaths/core/ExtrusionPath.h"

namespace mixengine {

/// `outermost`: the area inside the adhesion extruder's outermost line(s) (closed polygons);
/// `outer_width_um`: that line's width; `adhesion_extruder`: its extruder; `used`: the group's extruders.
std::vector<ExtrusionPath> otherExtruderSkirts(const Settings& global, const std::vector<Settings>* extruders,
                                               const Paths& outermost, coord_um outer_width_um,
                                               int adhesion_extruder, const std::set<int>& used);

/// The area inside the outermost of `lines` (closed loops): what otherExtruderSkirts goes around.
Paths areaInsideOutermost(const std::vector<ExtrusionPath>& lines);

}  // namespace mixengine
