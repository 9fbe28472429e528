#pragma once
// Writes the layers of a PrintPlan through a GCodeExport: ;LAYER:n, G92 E0 in absolute mode (when
// the flavor resets E each layer, gcode/Flavor.h), the plan's steps, and
// ;TIME_ELAPSED: at the end of each layer. As CuraEngine 4.13, a layer with nothing to print (no
// step but ;TYPE: and ;MESH: markers and its fan, which every layer sets again: e.g. the top layer of a model
// whose last cut is too thin for a wall) is left out — no ;LAYER: line, no Z move — though ;LAYER_COUNT:
// still counts it, and the layers after it keep their numbers. Returns one text chunk per layer, empty for a
// layer left out (Cura's socket sends them one by one; the CLI joins them).
#include <string>
#include <vector>

#include "gcode/GCodeExport.h"
#include "gcode/Header.h"
#include "gcode/StartEndCode.h"
#include "gcode/WipeScript.h"
#include "planning/LayerPlan.h"

namespace mixengine {

struct WrittenLayers {
    std::vector<std::string> chunks;  ///< one per layer, ";LAYER:n" first (empty: left out)
    Point3 min{INT64_MAX, INT64_MAX, INT64_MAX};
    Point3 max{INT64_MIN, INT64_MIN, INT64_MIN};
};

/// What a tool change needs of one extruder train. Switching away from it, as CuraEngine 4.13: its
/// switch retraction (when retraction_enable), the z-hop after a switch, E reset, its end code;
/// then T<n> of the new one, E reset, the new one's start code, and the new one's extra prime owed
/// for its next prime (when retraction_enable). Temperatures are plan steps (planning/SwitchTemperatures.h).
struct ExtruderOutput {
    ToolChange change;
    std::string start_code;          ///< machine_extruder_start_code, written after T<n>
    std::string end_code;            ///< machine_extruder_end_code, written before switching away
    bool retraction_enabled = true;  ///< retraction_enable
    /// switch_extruder_retraction_amount, switch_extruder_retraction_speed, switch_extruder_prime_speed
    RetractionConfig switch_retraction;
    coord_um switch_hop_um = 0;         ///< retraction_hop_after_extruder_switch(_height) (0 = none)
    double switch_extra_prime_mm3 = 0;  ///< switch_extruder_extra_prime_amount
    PrimeTrain prime;                   ///< its first use (Prime steps)
    WipeScriptConfig wipe;              ///< clean_between_layers (WipeScript steps)
};

struct PlanWriterParams {
    double layer_change_speed_mm_s = 10;    ///< Z moves
    std::vector<ExtruderOutput> extruders;  ///< index = extruder_nr (needed for SetExtruder steps)
};

WrittenLayers writePlan(const PrintPlan& plan, const PlanWriterParams& params, GCodeExport& gcode);

/// What the steps of a plan's layers refer to by index (PlanStep::mesh_index, PlanStep::mix): the
/// plan's own tables or copies of them, alive while layers are written.
struct PlanTables {
    const std::vector<std::string>& mesh_names;
    const std::vector<MixVector>& mixes;
    const std::vector<std::array<std::uint8_t, 3>>& outlet_colors;  ///< PlanStep::outlet_color
};

/// One layer as writePlan() writes it, numbered `number` (";LAYER:<number>"): its chunk is appended
/// to out.chunks. Writing a plan's layers in order through one GCodeExport gives writePlan()'s text.
void writeLayer(const PlannedLayer& layer, int number, const PlanTables& tables,
                const PlanWriterParams& params, GCodeExport& gcode, WrittenLayers& out);

}  // namespace mixengine
