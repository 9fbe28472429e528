#include "planning/Cooling.h"

#include <algorithm>
#include <cmath>

namespace mixengine {

double retractSeconds(const Settings& s) {
    const double speed = s.velocityMmPerS(key::retraction_retract_speed);
    if (!s.boolean(key::retraction_enable) || speed <= 0)
        return 0;
    return s.millimetres(key::retraction_amount) / speed;
}

CoolingParams coolingParams(const Settings& s) {
    CoolingParams p;
    p.fan_enabled = s.boolean(key::cool_fan_enabled);
    p.fan_min_ratio = s.ratio(key::cool_fan_speed_min);
    p.fan_max_ratio = s.ratio(key::cool_fan_speed_max);
    p.fan_first_ratio = s.ratio(key::cool_fan_speed_0);
    p.fan_full_layer = static_cast<int>(s.integer(key::cool_fan_full_layer));
    p.min_layer_time_s = s.durationSeconds(key::cool_min_layer_time);
    p.fan_max_layer_time_s = s.durationSeconds(key::cool_min_layer_time_fan_speed_max);
    p.min_speed_mm_s = s.velocityMmPerS(key::cool_min_speed);
    p.lift_head = s.boolean(key::cool_lift_head);
    if (!s.boolean(key::machine_center_is_zero))
        p.bed_middle_um = {s.lengthMicrons(key::machine_width) / 2, s.lengthMicrons(key::machine_depth) / 2};
    p.travel_speed_mm_s = s.velocityMmPerS(key::speed_travel);
    p.retract_seconds = retractSeconds(s);
    return p;
}

namespace {

/// The fan for a layer whose estimate (LayerEstimate::extrude_s + unretracted_s, before any
/// slow-down) is `seconds`.
double fanRatio(const CoolingParams& p, int layer, double seconds) {
    if (!p.fan_enabled)
        return 0;
    double regular = p.fan_min_ratio;
    if (seconds < p.min_layer_time_s) {
        regular = p.fan_max_ratio;
    } else if (seconds < p.fan_max_layer_time_s && p.fan_max_layer_time_s > p.min_layer_time_s) {
        const double t = (p.fan_max_layer_time_s - seconds) / (p.fan_max_layer_time_s - p.min_layer_time_s);
        regular = p.fan_min_ratio + (p.fan_max_ratio - p.fan_min_ratio) * t;
    }
    const int full = p.fan_full_layer - 1;  // 0-based layer at full speed
    if (layer >= full || full <= 0)
        return regular;
    return p.fan_first_ratio + (regular - p.fan_first_ratio) * double(std::max(layer, 0)) / double(full);
}

/// The factor CuraEngine 4.13 slows a layer's extrusions by so that it takes `min_layer_time_s`
/// (1: no slow-down): the extrusions take the minimum time minus the travel (at least 1 s), but the
/// slowest extrusion not under `min_speed_mm_s`.
double slowDownFactor(const PlannedLayer& layer, const LayerEstimate& estimate, const CoolingParams& p) {
    const double minimum_extrude_s = std::max(p.min_layer_time_s - estimate.travel_s, 1.0);
    double factor = estimate.extrude_s / minimum_extrude_s;
    for (const PlanStep& step : layer.steps) {
        if (step.kind == PlanStep::Kind::Extrude && step.speed_mm_s > 0 &&
            step.speed_mm_s * factor < p.min_speed_mm_s)
            factor = p.min_speed_mm_s / step.speed_mm_s;
    }
    return std::min(factor, 1.0);
}

/// The lift at the end of a layer `extra_s` too short: 20 mm from the head's last position towards
/// the middle of the bed.
PlanStep liftHead(const PlannedLayer& layer, Point2 head, const CoolingParams& p, double extra_s) {
    for (const PlanStep& step : layer.steps) {
        if (step.kind == PlanStep::Kind::Travel || step.kind == PlanStep::Kind::Extrude)
            head = step.to;
    }
    constexpr double kTowardsMiddleUm = 20'000;
    const double dx = double(head.X - p.bed_middle_um.X), dy = double(head.Y - p.bed_middle_um.Y);
    const double length = std::hypot(dx, dy);
    PlanStep lift;
    lift.kind = PlanStep::Kind::LiftHead;
    lift.to = head;
    if (length > 0) {
        lift.to.X -= static_cast<coord_um>(std::llround(dx * kTowardsMiddleUm / length));
        lift.to.Y -= static_cast<coord_um>(std::llround(dy * kTowardsMiddleUm / length));
    }
    lift.speed_mm_s = p.travel_speed_mm_s;
    lift.dwell_seconds = extra_s;
    return lift;
}

}  // namespace

CoolingParams raftCooling(const CoolingParams& model, double raft_fan_ratio) {
    CoolingParams p = model;
    if (!p.fan_enabled) {  // CuraEngine zeroes the fan speeds, then sets the raft's
        p.fan_enabled = true;
        p.fan_max_ratio = 0;
    }
    p.fan_min_ratio = raft_fan_ratio;
    p.fan_first_ratio = raft_fan_ratio;
    p.fan_full_layer = 0;
    return p;
}

std::vector<double> stepSeconds(const PlannedLayer& layer, Point2 head) {
    std::vector<double> seconds(layer.steps.size(), 0.0);
    for (std::size_t i = 0; i < layer.steps.size(); ++i) {
        const PlanStep& step = layer.steps[i];
        if (step.kind != PlanStep::Kind::Travel && step.kind != PlanStep::Kind::Extrude)
            continue;
        seconds[i] = step.speed_mm_s > 0 ? distanceMm(head, step.to) / step.speed_mm_s : 0;
        head = step.to;
    }
    return seconds;
}

double naiveLayerSeconds(const PlannedLayer& layer, Point2 start) {
    double seconds = 0;
    for (double s : stepSeconds(layer, start))
        seconds += s;
    return seconds;
}

LayerEstimate estimateLayer(const PlannedLayer& layer, Point2 start, double retract_seconds) {
    LayerEstimate estimate;
    const std::vector<double> seconds = stepSeconds(layer, start);
    bool leading = true;         // still in the travel the layer starts with
    bool retracted = false;      // in a travel that retracted
    double leading_speed = 0;    // of that travel
    Point2 leading_end = start;  // where it ends
    for (std::size_t i = 0; i < layer.steps.size(); ++i) {
        const PlanStep& step = layer.steps[i];
        if (step.kind == PlanStep::Kind::Extrude) {
            leading = retracted = false;
            estimate.extrude_s += seconds[i];
        } else if (step.kind != PlanStep::Kind::Travel) {
            retracted = false;
        } else if (leading) {
            leading_speed = step.speed_mm_s, leading_end = step.to;
        } else {
            retracted = retracted || step.retract;
            const double retraction_s = step.retract ? retract_seconds : 0;
            estimate.travel_s += seconds[i] + retraction_s;
            estimate.unretracted_s += (retracted ? 0 : seconds[i]) + 0.5 * retraction_s;
        }
    }
    const double leading_s = leading_speed > 0 ? distanceMm(start, leading_end) / leading_speed : 0;
    estimate.travel_s += leading_s;
    estimate.unretracted_s += leading_s;
    return estimate;
}

void applyCooling(PlannedLayer& layer, Point2 start, const CoolingParams& params) {
    const LayerEstimate estimate = estimateLayer(layer, start, params.retract_seconds);
    if (estimate.extrude_s + estimate.travel_s < params.min_layer_time_s && estimate.extrude_s > 0) {
        const double factor = slowDownFactor(layer, estimate, params);
        for (PlanStep& step : layer.steps) {
            if (step.kind == PlanStep::Kind::Extrude)
                step.speed_mm_s *= factor;
        }
        const double extra_s = params.min_layer_time_s - estimate.extrude_s / factor - estimate.travel_s;
        if (params.lift_head && extra_s > 0.1)
            layer.steps.push_back(liftHead(layer, start, params, extra_s));
    }
    const double fan_seconds = estimate.extrude_s + estimate.unretracted_s;
    for (PlanStep& step : layer.steps) {
        if (step.kind == PlanStep::Kind::SetFan && !step.fan_fixed)
            step.fan_ratio = fanRatio(params, layer.index, fan_seconds);
    }
}

}  // namespace mixengine
