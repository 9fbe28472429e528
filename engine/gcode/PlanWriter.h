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

struct PlanWriterParams {
    double layer_change_speed_mm_s = 10;  ///< Z moves
    bool reset_e_each_layer = true;       ///< G92 E0 at each layer start in absolute mode
};

WrittenLayers writePlan(const PrintPlan& plan, const PlanWriterParams& params, GCodeExport& gcode);

}  // namespace mixengine
