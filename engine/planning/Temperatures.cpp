#include "planning/Temperatures.h"

#include <algorithm>
#include <cstdlib>

#include "common/Error.h"
#include "planning/Cooling.h"

namespace mixengine {

std::vector<FlowTemperature> parseFlowTemperatureGraph(const std::string& text) {
    std::vector<double> numbers;
    const char* p = text.c_str();
    while (*p != '\0') {
        if (std::isdigit(static_cast<unsigned char>(*p)) || *p == '-' || *p == '.') {
            char* end = nullptr;
            numbers.push_back(std::strtod(p, &end));
            if (end == p)
                throw InputError("setting 'material_flow_temp_graph': value '" + text +
                                 "' is not a list of pairs");
            p = end;
        } else {
            ++p;
        }
    }
    if (numbers.size() % 2 != 0)
        throw InputError("setting 'material_flow_temp_graph': value '" + text + "' is not a list of pairs");
    std::vector<FlowTemperature> graph;
    for (std::size_t i = 0; i < numbers.size(); i += 2)
        graph.push_back({numbers[i], numbers[i + 1]});
    return graph;
}

TemperatureParams temperatureParams(const Settings& global, const Settings& extruder) {
    TemperatureParams p;
    p.heated_bed = global.boolean(key::machine_heated_bed);
    p.bed_c = global.temperatureCelsius(key::material_bed_temperature);
    p.bed_layer0_c = global.temperatureCelsius(key::material_bed_temperature_layer_0);
    p.nozzle = nozzleTemperatureParams(extruder);
    return p;
}

NozzleTemperatureParams nozzleTemperatureParams(const Settings& extruder) {
    NozzleTemperatureParams n;
    n.enabled = extruder.boolean(key::machine_nozzle_temp_enabled);
    n.print_c = extruder.temperatureCelsius(key::material_print_temperature);
    n.layer0_c = extruder.temperatureCelsius(key::material_print_temperature_layer_0);
    n.flow_dependent = extruder.boolean(key::material_flow_dependent_temperature);
    if (n.flow_dependent)
        n.graph = parseFlowTemperatureGraph(extruder.text(key::material_flow_temp_graph));
    n.heat_up_c_per_s = extruder.real(key::machine_nozzle_heat_up_speed);
    n.cool_down_c_per_s = extruder.real(key::machine_nozzle_cool_down_speed);
    n.extrusion_cool_c_per_s = extruder.real(key::material_extrusion_cool_down_speed);
    return n;
}

double flowTemperature(const NozzleTemperatureParams& p, double flow_mm3_s) {
    if (!p.flow_dependent || p.graph.empty())
        return p.print_c;
    if (p.graph.size() == 1 || flow_mm3_s < p.graph.front().flow_mm3_s)
        return p.graph.front().temperature_c;
    for (std::size_t i = 1; i < p.graph.size(); ++i) {
        const FlowTemperature& a = p.graph[i - 1];
        const FlowTemperature& b = p.graph[i];
        if (b.flow_mm3_s >= flow_mm3_s) {
            const double span = b.flow_mm3_s - a.flow_mm3_s;
            return span > 0 ? a.temperature_c +
                                  (b.temperature_c - a.temperature_c) * (flow_mm3_s - a.flow_mm3_s) / span
                            : b.temperature_c;
        }
    }
    return p.graph.back().temperature_c;
}

namespace {

/// Seconds the nozzle needs from `from_c` to `to_c` while printing.
double secondsBetween(const NozzleTemperatureParams& p, double from_c, double to_c) {
    const double speed = to_c > from_c ? p.heat_up_c_per_s - p.extrusion_cool_c_per_s
                                       : p.cool_down_c_per_s + p.extrusion_cool_c_per_s;
    return speed > 0 ? std::abs(to_c - from_c) / speed : 0.0;
}

/// The temperature a layer wants: its average flow through the graph (the plan's first layer — the
/// raft's base under a raft — the layer-0 value).
double wantedTemperature(const NozzleTemperatureParams& p, const PlannedLayer& layer, Point2 start,
                         bool first) {
    if (first && p.layer0_c != 0)
        return p.layer0_c;
    if (!p.flow_dependent)
        return p.print_c;
    const std::vector<double> seconds = stepSeconds(layer, start);
    double volume = 0, extruding = 0;
    for (std::size_t i = 0; i < seconds.size(); ++i) {
        if (layer.steps[i].kind == PlanStep::Kind::Extrude) {
            volume += layer.steps[i].volume_mm3;
            extruding += seconds[i];
        }
    }
    return flowTemperature(p, extruding > 0 ? volume / extruding : 0.0);
}

PlanStep temperatureStep(PlanStep::Kind kind, double celsius) {
    PlanStep step;
    step.kind = kind;
    step.extruder = -1;  // the active nozzle
    step.temperature_c = celsius;
    return step;
}

/// Inserts `step` into `layer` so that `before_end_s` of the layer's time follows it.
void insertBeforeEnd(PlannedLayer& layer, Point2 start, double before_end_s, const PlanStep& step) {
    const std::vector<double> seconds = stepSeconds(layer, start);
    double after = 0;
    std::size_t at = layer.steps.size();
    while (at > 0 && after + seconds[at - 1] <= before_end_s) {
        after += seconds[at - 1];
        --at;
    }
    if (at > 0 && after < before_end_s)
        --at;  // the step during which the time is reached
    layer.steps.insert(layer.steps.begin() + static_cast<std::ptrdiff_t>(at), step);
}

Point2 lastPosition(const PlannedLayer& layer, Point2 start) {
    for (auto it = layer.steps.rbegin(); it != layer.steps.rend(); ++it) {
        if (it->kind == PlanStep::Kind::Travel || it->kind == PlanStep::Kind::Extrude)
            return it->to;
    }
    return start;
}

}  // namespace

void TemperatureSteps::planNozzle(PrintPlan& plan, std::size_t i) {
    const NozzleTemperatureParams& p = params_.nozzle;
    if (i == 0) {
        current_c_ = wantedTemperature(p, plan.layers[0], start_, true);
        return;
    }
    const double wanted = wantedTemperature(p, plan.layers[i], start_, false);
    if (wanted == current_c_)
        return;
    PlannedLayer& before = plan.layers[i - 1];
    const double lead_s =
        std::min(naiveLayerSeconds(before, previous_start_), 0.5 * secondsBetween(p, current_c_, wanted));
    insertBeforeEnd(before, previous_start_, lead_s,
                    temperatureStep(PlanStep::Kind::SetNozzleTemperature, wanted));
    current_c_ = wanted;
}

void TemperatureSteps::finalizeBefore(PrintPlan& plan, std::size_t end) {
    for (; final_ < end; ++final_) {
        if (final_ == 1 && params_.heated_bed && params_.bed_c != params_.bed_layer0_c) {
            std::vector<PlanStep>& steps = plan.layers[1].steps;
            steps.insert(steps.begin(), temperatureStep(PlanStep::Kind::SetBedTemperature, params_.bed_c));
        }
    }
}

std::size_t TemperatureSteps::add(PrintPlan& plan) {
    for (; planned_ < plan.layers.size(); ++planned_) {
        if (single_ && params_.nozzle.enabled)
            planNozzle(plan, planned_);
        previous_start_ = start_;
        start_ = lastPosition(plan.layers[planned_], start_);
        if (planned_ > 0)
            finalizeBefore(plan, planned_);  // layers before this one are final
    }
    return final_;
}

std::size_t TemperatureSteps::finish(PrintPlan& plan) {
    add(plan);
    finalizeBefore(plan, plan.layers.size());
    return final_;
}

void planTemperatures(PrintPlan& plan, const TemperatureParams& params, bool single_extruder, Point2 start) {
    TemperatureSteps(params, single_extruder, start).finish(plan);
}

}  // namespace mixengine
