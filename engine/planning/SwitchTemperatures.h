#pragma once
// Nozzle temperatures of a print with several extruders, as CuraEngine 4.13's LayerPlanBuffer sets
// them. The plan is cut into extruder runs (planning/ExtruderRuns.h). Every run wants a printing
// temperature: on layer 0 material_print_temperature_layer_0 (when not 0), else
// material_print_temperature or, flow dependent, the graph's value for the run's average flow
// (planning/Temperatures.h). Its start temperature is material_initial_print_temperature when that is
// set, the extruder printed before in this print and the run before is not its own; else the printing
// temperature. For every run after the first, looking back at most six layers (CuraEngine's buffer):
//   - after a run of the same extruder: M104 to the start temperature, half the time the nozzle
//     needs to get there before that run ends (the single-extruder rule);
//   - machine_extruders_share_heater: that rule, for the one heater, on the extruder before;
//   - otherwise (planning/PreheatModel.h, rates of the extruder's train):
//       * standby and preheat: the time since the extruder last printed (not in view: it is taken
//         as cooled to material_standby_temperature) decides how far it cools and when it must heat
//         again; M104 T<n> to the start temperature goes that long (+1 s) before the run, in the runs
//         of other extruders before it. The temperature it is left at when switched away from is
//         the lowest it can reach in time (at most down to the standby temperature), or the start
//         temperature when it is idle for less than machine_min_cool_heat_time_window;
//       * final temperature: material_final_print_temperature (when not 0) is set in the extruder's
//         last runs before the switch, when the model says cooling must begin to reach it at the end;
//         a reheat of the single-extruder rule in those runs is dropped;
//       * printing temperature: with an initial temperature, M104 to the printing temperature
//         before the run's first extrusion.
//   At the switch into a run: M109 (wait) for its start temperature, then the extruder switched away
//   from to its standby temperature — 0 when that extruder prints no model, support or adhesion after
//   this layer.
// Steps are SetNozzleTemperature with `extruder` set; the writer drops those that change nothing
// (gcode/TemperatureCommands.h). machine_nozzle_temp_enabled = false: no commands for that train.
#include <vector>

#include "planning/LayerPlan.h"
#include "planning/Temperatures.h"
#include "settings/Settings.h"

namespace mixengine {

struct TrainTemperatureParams {
    NozzleTemperatureParams nozzle;  ///< printing temperatures and heater rates of the train
    double initial_c = 0;            ///< material_initial_print_temperature (0 = none)
    double final_c = 0;              ///< material_final_print_temperature (0 = none)
    double standby_c = 150;          ///< material_standby_temperature
    double min_window_s = 50;        ///< machine_min_cool_heat_time_window
};

struct SwitchTemperatureParams {
    std::vector<TrainTemperatureParams> trains;  ///< index = extruder_nr
    bool share_heater = false;                   ///< machine_extruders_share_heater
    std::vector<int> last_layer;  ///< per extruder: last layer with its model, support or adhesion (−1: none)
};

std::vector<TrainTemperatureParams> trainTemperatureParams(const std::vector<Settings>& extruders);

/// Adds the temperature steps described above. The first layer starts with `start_extruder` active,
/// the head at `start`.
void planSwitchTemperatures(PrintPlan& plan, const SwitchTemperatureParams& params, int start_extruder,
                            Point2 start);

}  // namespace mixengine
