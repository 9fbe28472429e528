#pragma once
// Writes the layers of a PrintPlan through a GCodeExport: ;LAYER:n, the plan's steps, and
// ;TIME_ELAPSED: at the end of each layer. Returns one text chunk per layer (Cura's socket sends
// them one by one; the CLI joins them).
#include <string>
#include <vector>

#include "gcode/GCodeExport.h"
#include "gcode/Header.h"
#include "planning/LayerPlan.h"

namespace mixengine {

struct WrittenLayers {
    std::vector<std::string> chunks;  ///< one per layer, ";LAYER:n" first
    Point3 min{INT64_MAX, INT64_MAX, INT64_MAX};
    Point3 max{INT64_MIN, INT64_MIN, INT64_MIN};
};

/// What a tool change needs of one extruder train.
struct ExtruderOutput {
    ToolChange change;
    std::string start_code;            ///< machine_extruder_start_code, written after T<n>
    std::string end_code;              ///< machine_extruder_end_code, written before switching away
    double print_temperature_c = 0;    ///< waited for after switching to this extruder (0 = none)
    double standby_temperature_c = 0;  ///< set when switching away from it (0 = none)
};

struct PlanWriterParams {
    double layer_change_speed_mm_s = 10;    ///< Z moves
    bool reset_e_each_layer = true;         ///< G92 E0 at each layer start in absolute mode
    std::vector<ExtruderOutput> extruders;  ///< index = extruder_nr (needed for SetExtruder steps)
};

WrittenLayers writePlan(const PrintPlan& plan, const PlanWriterParams& params, GCodeExport& gcode);

}  // namespace mixengine
