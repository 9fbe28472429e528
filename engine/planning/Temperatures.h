#pragma once
// Temperatures during the print, as CuraEngine 4.13 changes them after the start code:
//   - bed: at the start of the plan's second layer, material_bed_temperature when it differs from
//     the layer-0 value (machine_heated_bed only), without waiting;
//   - nozzle (one extruder in the print): every layer wants a temperature — the plan's first layer
//     (under a raft: the raft's base, as CuraEngine's "initial layer")
//     material_print_temperature_layer_0 (when not 0), later layers material_print_temperature, or
//     with material_flow_dependent_temperature the temperature material_flow_temp_graph gives for
//     the layer's average flow (mm³/s of extruded volume over the time spent extruding). When the
//     wanted temperature changes, `M104` is set in the layer before, half the time it takes the
//     nozzle to get there before that layer ends (machine_nozzle_heat_up_speed /
//     machine_nozzle_cool_down_speed, less / plus material_extrusion_cool_down_speed while
//     printing), as CuraEngine's preheat model does. machine_nozzle_temp_enabled=false: none.
//     With several extruders in the print: planning/SwitchTemperatures.h instead.
// Layer times are the planner's distance / speed estimates (planning/Cooling.h), after cooling.
#include <vector>

#include "planning/LayerPlan.h"
#include "settings/Settings.h"

namespace mixengine {

/// One point of material_flow_temp_graph: flow in mm³/s, temperature in °C.
struct FlowTemperature {
    double flow_mm3_s = 0;
    double temperature_c = 0;
};

struct NozzleTemperatureParams {
    bool enabled = true;          ///< machine_nozzle_temp_enabled
    double print_c = 200;         ///< material_print_temperature
    double layer0_c = 0;          ///< material_print_temperature_layer_0 (0 = print_c)
    bool flow_dependent = false;  ///< material_flow_dependent_temperature
    std::vector<FlowTemperature> graph;
    double heat_up_c_per_s = 2;           ///< machine_nozzle_heat_up_speed
    double cool_down_c_per_s = 2;         ///< machine_nozzle_cool_down_speed
    double extrusion_cool_c_per_s = 0.7;  ///< material_extrusion_cool_down_speed
};

struct TemperatureParams {
    bool heated_bed = true;
    double bed_c = 60;               ///< material_bed_temperature
    double bed_layer0_c = 60;        ///< material_bed_temperature_layer_0
    NozzleTemperatureParams nozzle;  ///< of the only extruder used
};

TemperatureParams temperatureParams(const Settings& global, const Settings& extruder);

/// The nozzle's values of one extruder train.
NozzleTemperatureParams nozzleTemperatureParams(const Settings& extruder);

/// material_flow_temp_graph text ("[[3.5, 200], [7.0, 240]]"); throws InputError naming the key.
std::vector<FlowTemperature> parseFlowTemperatureGraph(const std::string& text);

/// The temperature the graph gives for `flow_mm3_s` (CuraEngine's rule: clamped to the ends,
/// linear in between; print_c when not flow dependent or the graph is empty).
double flowTemperature(const NozzleTemperatureParams& p, double flow_mm3_s);

/// Adds the bed and nozzle temperature steps to `plan` (see above). `single_extruder`: the print
/// uses one extruder (multi-extruder prints change temperatures at tool changes instead).
void planTemperatures(PrintPlan& plan, const TemperatureParams& params, bool single_extruder, Point2 start);

/// planTemperatures() for a plan that grows a layer at a time, with the same result: add() after
/// layers were appended, finish() when the plan is complete. A layer is final (no later call
/// changes it) once the layer after it is added: its nozzle step depends on that layer's wish.
class TemperatureSteps {
  public:
    TemperatureSteps(const TemperatureParams& params, bool single_extruder, Point2 start)
        : params_(params), single_(single_extruder), start_(start) {}
    /// Plans the layers appended since the last call; returns how many layers at the front of
    /// `plan` are final.
    std::size_t add(PrintPlan& plan);
    /// Plans what is left; every layer is final (returns their count).
    std::size_t finish(PrintPlan& plan);

  private:
    void planNozzle(PrintPlan& plan, std::size_t layer);
    void finalizeBefore(PrintPlan& plan, std::size_t end);  ///< the bed step, then final up to `end`

    TemperatureParams params_;
    bool single_;
    Point2 start_;           ///< where the next layer to plan starts
    Point2 previous_start_;  ///< where the layer before it started
    double current_c_ = 0;   ///< the nozzle temperature wanted so far
    std::size_t planned_ = 0, final_ = 0;
};

}  // namespace mixengine
