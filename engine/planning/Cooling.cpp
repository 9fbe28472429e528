#include "planning/Cooling.h"

#include <algorithm>
#include <cmath>

namespace mixengine {

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
    return p;
}

namespace {

/// Time spent extruding and travelling, separately.
std::pair<double, double> splitSeconds(const PlannedLayer& layer, Point2 head) {
    const std::vector<double> seconds = stepSeconds(layer, head);
    double extruding = 0, travelling = 0;
    for (std::size_t i = 0; i < seconds.size(); ++i)
        (layer.steps[i].kind == PlanStep::Kind::Extrude ? extruding : travelling) += seconds[i];
    return {extruding, travelling};
}

double fanRatio(const CoolingParams& p, int layer, double seconds) {
    if (!p.fan_enabled)
        return 0;
    double regular = p.fan_min_ratio;
    if (seconds <= p.min_layer_time_s) {
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
    const auto [extruding, travelling] = splitSeconds(layer, start);
    return extruding + travelling;
}

void applyCooling(PlannedLayer& layer, Point2 start, const CoolingParams& params) {
    const auto [extruding, travelling] = splitSeconds(layer, start);
    double seconds = extruding + travelling;
    if (seconds < params.min_layer_time_s && extruding > 0) {
        const double wanted_extruding = params.min_layer_time_s - travelling;
        const double factor = std::clamp(extruding / std::max(wanted_extruding, 1e-9), 0.0, 1.0);
        for (PlanStep& step : layer.steps) {
            if (step.kind == PlanStep::Kind::Extrude)
                step.speed_mm_s =
                    std::max(std::min(params.min_speed_mm_s, step.speed_mm_s), step.speed_mm_s * factor);
        }
        seconds = naiveLayerSeconds(layer, start);
        if (params.lift_head && params.min_layer_time_s - seconds > 0.1)
            layer.steps.push_back(liftHead(layer, start, params, params.min_layer_time_s - seconds));
    }
    for (PlanStep& step : layer.steps) {
        if (step.kind == PlanStep::Kind::SetFan && !step.fan_fixed)
            step.fan_ratio = fanRatio(params, layer.index, seconds);
    }
}

}  // namespace mixengine
