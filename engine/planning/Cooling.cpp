#include "planning/Cooling.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <vector>

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

namespace {

/// CuraEngine's integer length: the square root of the squared length, truncated.
coord_um lengthUm(const Point2& v) {
    return static_cast<coord_um>(std::sqrt(double(v.X * v.X + v.Y * v.Y)));
}

coord_um length2Um2(const Point2& v) {
    return v.X * v.X + v.Y * v.Y;
}

Point2 minus(const Point2& a, const Point2& b) {
    return {a.X - b.X, a.Y - b.Y};
}

coord_um dotUm2(const Point2& a, const Point2& b) {
    return a.X * b.X + a.Y * b.Y;
}

/// The squared distance of `p` from the line through `a` and `b` (all of it, not the segment).
coord_um distance2FromLine(const Point2& p, const Point2& a, const Point2& b) {
    const Point2 ab = minus(b, a), ap = minus(p, a);
    const coord_um ab2 = length2Um2(ab), ap2 = length2Um2(ap);
    if (ab2 == 0)
        return ap2;
    const double along = double(dotUm2(ab, ap));
    return std::max<coord_um>(0, ap2 - static_cast<coord_um>(along * along / double(ab2)));
}

/// A run of motion steps of one kind: travel, or the Extrude steps of one path.
struct Unit {
    bool travel = false;
    std::size_t first = 0, last = 0;  ///< step indices (inclusive)
    int extrudes = 0;                 ///< Extrude steps in it
    bool mergeable = false;
    coord_um width_um = 0;
    double speed_mm_s = 0;
};

/// The line a first path grew into: its points after the start (the travel's end, which merging
/// moves), the flow against the first line's own, and that line's volume per millimetre.
struct Merged {
    std::vector<Point2> points;
    double flow = 1;
    double volume_per_mm = 0;
};

/// The state of CuraEngine's walk over one extruder's paths.
struct Walk {
    std::vector<PlanStep>& steps;
    const std::vector<Unit>& units;
    GapMergeParams params;
    std::vector<std::optional<Merged>> merged;  ///< per unit
    std::vector<bool> dropped;                  ///< per step
    coord_um error_area = 0;
};

Point2 endOf(const Walk& w, std::size_t unit) {
    return w.steps[w.units[unit].last].to;
}

/// The points of path `unit` after its start, merged or not.
std::vector<Point2> pointsOf(const Walk& w, std::size_t unit) {
    if (w.merged[unit])
        return w.merged[unit]->points;
    return {endOf(w, unit)};
}

coord_um pathLengthUm(Point2 from, const std::vector<Point2>& points) {
    coord_um length = 0;
    for (const Point2& p : points) {
        length += lengthUm(minus(p, from));
        from = p;
    }
    return length;
}

/// What merging the second line into the first would make: CuraEngine's mergeLinesSideBySide.
struct Pair {
    std::size_t first = 0, second = 0;
    Point2 first_start, second_start;
};

bool mergeSideBySide(Walk& w, const Pair& pair, std::vector<Point2>& points, double& flow,
                     std::optional<Point2>& new_start) {
    const bool already = w.merged[pair.first].has_value();
    const coord_um width = w.units[pair.first].width_um;
    const coord_um first_length = pathLengthUm(pair.first_start, points);
    const auto first_length_flow = static_cast<coord_um>(double(first_length) * flow);
    Point2 first_mean = already ? points.front() : pair.first_start;
    if (!already) {
        for (const Point2& p : points)
            first_mean = {first_mean.X + p.X, first_mean.Y + p.Y};
        const auto n = static_cast<coord_um>(points.size() + 1);
        first_mean = {first_mean.X / n, first_mean.Y / n};
    }
    const Point2 second_end = endOf(w, pair.second);
    const auto second_length_flow = lengthUm(minus(second_end, pair.second_start));
    const Point2 second_mid{(pair.second_start.X + second_end.X) / 2,
                            (pair.second_start.Y + second_end.Y) / 2};

    coord_um new_length = first_length;
    coord_um new_error = 0;
    bool replace_last = false;
    if (already) {
        const std::size_t n = points.size();
        coord_um merged_part = 0;
        if (n > 1) {
            merged_part = lengthUm(minus(points[n - 2], second_mid));
            const double off = std::sqrt(double(distance2FromLine(second_mid, points[n - 2], points[n - 1])));
            new_error = static_cast<coord_um>(off * double(merged_part) / 2);
        }
        if (n > 1 && w.error_area + new_error < merged_part * w.params.max_deviation_um)
            new_length += merged_part - lengthUm(minus(points[n - 2], points[n - 1]));
        else
            new_length += lengthUm(minus(points.back(), second_mid));
        replace_last = n > 1 && w.error_area + new_error < width * width;
    } else {
        new_length +=
            lengthUm(minus(second_mid, first_mean)) - lengthUm(minus(points.back(), pair.first_start));
    }
    const double new_flow = double(first_length_flow + second_length_flow) / double(new_length);
    if (new_flow > 3.0 * double(w.params.nozzle_um) / double(width))
        return false;  // too wide
    if (!already) {
        new_start = first_mean;
        points = {second_mid};
        w.error_area = 0;
    } else if (replace_last) {
        points.back() = second_mid;
        w.error_area += new_error;
    } else {
        points.push_back(second_mid);
        w.error_area = 0;
    }
    flow = new_flow;
    return true;
}

/// CuraEngine's tryMerge: whether the lines lie side by side closely enough, then the merge.
bool tryMerge(Walk& w, const Pair& pair, std::vector<Point2>& points, double& flow,
              std::optional<Point2>& new_start) {
    const bool already = w.merged[pair.first].has_value();
    const coord_um width = w.units[pair.first].width_um;
    const coord_um width2 = width * width;
    const Point2 first_end = points.back();
    const Point2 second_end = endOf(w, pair.second);
    if (length2Um2(minus(first_end, pair.second_start)) < width2 ||
        length2Um2(minus(pair.first_start, second_end)) < width2) {
        const Point2 a = minus(first_end, pair.first_start), b = minus(second_end, pair.second_start);
        constexpr coord_um kSlightCurveUm2 = 400;  // 20 µm of inaccuracy in the dot product
        if (dotUm2(a, b) + kSlightCurveUm2 > lengthUm(a) * lengthUm(b))
            return false;  // in line with each other
    }
    const Point2 leave =
        already ? points.back()
                : Point2{(pair.first_start.X + first_end.X) / 2, (pair.first_start.Y + first_end.Y) / 2};
    const Point2 target{(pair.second_start.X + second_end.X) / 2, (pair.second_start.Y + second_end.Y) / 2};
    const Point2 direction = minus(target, leave);
    if (length2Um2(direction) > 25 * width2 || (direction.X == 0 && direction.Y == 0))
        return false;
    const Point2 target_ahead{target.X + direction.X, target.Y + direction.Y};
    const Point2 leave_ahead{leave.X + direction.X, leave.Y + direction.Y};
    const double side2 = 2.25 * double(width2);
    if (double(distance2FromLine(first_end, target, target_ahead)) > side2 ||
        double(distance2FromLine(pair.second_start, leave, leave_ahead)) > side2 ||
        double(distance2FromLine(second_end, leave, leave_ahead)) > side2)
        return false;
    if (already && points.size() > 1 && points[points.size() - 2] == target)
        return false;
    return mergeSideBySide(w, pair, points, flow, new_start);
}

bool sameStyle(const Unit& a, const Unit& b) {
    return a.mergeable && b.mergeable && a.width_um == b.width_um && a.speed_mm_s == b.speed_mm_s;
}

/// Whether CuraEngine tries the pair at all: travel before the first and after the second, both
/// gap lines of one style, the second a single line and the first one too unless merged already.
bool mayTry(const Walk& w, std::size_t first, std::size_t second) {
    const std::vector<Unit>& u = w.units;
    return first > 1 && u[first - 1].travel && second + 1 < u.size() && u[second + 1].travel &&
           !u[first].travel && sameStyle(u[first], u[second]) && u[second].extrudes == 1 &&
           (w.merged[first].has_value() || u[first].extrudes == 1);
}

void dropUnits(Walk& w, std::size_t from, std::size_t to) {
    for (std::size_t k = from; k <= to; ++k) {
        for (std::size_t s = w.units[k].first; s <= w.units[k].last; ++s) {
            const PlanStep::Kind kind = w.steps[s].kind;
            if (kind == PlanStep::Kind::Travel || kind == PlanStep::Kind::Extrude)
                w.dropped[s] = true;
        }
    }
}

/// CuraEngine's walk over the paths of one extruder.
void walk(Walk& w, Point2 start) {
    if (w.units.empty())
        return;
    std::size_t first = 0;
    Point2 first_start = start;
    for (std::size_t second = 1; second < w.units.size(); ++second) {
        const Point2 second_start = endOf(w, second - 1);
        if (w.units[second].travel)
            continue;
        if (!w.units[first].mergeable || !mayTry(w, first, second)) {
            first = second, first_start = second_start;
            continue;
        }
        std::vector<Point2> points = pointsOf(w, first);
        double flow = w.merged[first] ? w.merged[first]->flow : 1.0;
        std::optional<Point2> new_start;
        if (!tryMerge(w, {first, second, first_start, second_start}, points, flow, new_start)) {
            first = second, first_start = second_start;
            continue;
        }
        if (!w.merged[first]) {
            const PlanStep& line = w.steps[w.units[first].last];
            const double length_mm = distanceMm(endOf(w, first - 1), line.to);
            w.merged[first] = Merged{{}, 1.0, length_mm > 0 ? line.volume_mm3 / length_mm : 0};
        }
        if (new_start)
            w.steps[w.units[first - 1].last].to = *new_start;
        w.merged[first]->points = std::move(points);
        w.merged[first]->flow = flow;
        dropUnits(w, first + 1, second);
    }
}

bool isMotion(PlanStep::Kind kind) {
    return kind == PlanStep::Kind::Travel || kind == PlanStep::Kind::Extrude;
}

bool endsExtruderPlan(PlanStep::Kind kind) {
    return kind == PlanStep::Kind::SetExtruder || kind == PlanStep::Kind::LiftHead ||
           kind == PlanStep::Kind::Prime || kind == PlanStep::Kind::WipeScript;
}

/// The units of steps [from, to): runs of travel, and runs of Extrude steps of one style.
std::vector<Unit> unitsOf(const std::vector<PlanStep>& steps, std::size_t from, std::size_t to) {
    std::vector<Unit> units;
    for (std::size_t s = from; s < to; ++s) {
        const PlanStep& step = steps[s];
        if (!isMotion(step.kind))
            continue;
        const bool travel = step.kind == PlanStep::Kind::Travel;
        Unit unit{travel, s, s, travel ? 0 : 1, !travel && step.mergeable, step.width_um, step.speed_mm_s};
        Unit* last = units.empty() ? nullptr : &units.back();
        if (last && last->travel && travel) {
            last->last = s;
        } else if (last && !last->travel && !travel && last->mergeable == unit.mergeable &&
                   last->width_um == unit.width_um && last->speed_mm_s == unit.speed_mm_s) {
            last->last = s;
            ++last->extrudes;
        } else {
            units.push_back(unit);
        }
    }
    return units;
}

/// The layer's steps again, without the dropped ones and with each merged line in place of its first.
std::vector<PlanStep> rebuilt(std::vector<PlanStep> steps, const std::vector<bool>& dropped,
                              const std::vector<std::optional<Merged>>& merged_at) {
    std::vector<PlanStep> out;
    out.reserve(steps.size());
    Point2 head{0, 0};
    for (std::size_t s = 0; s < steps.size(); ++s) {
        if (dropped[s])
            continue;
        if (!merged_at[s]) {
            if (isMotion(steps[s].kind))
                head = steps[s].to;
            out.push_back(std::move(steps[s]));
            continue;
        }
        const Merged& m = *merged_at[s];
        for (const Point2& p : m.points) {
            PlanStep line = steps[s];
            line.to = p;
            line.volume_mm3 = distanceMm(head, p) * m.volume_per_mm * m.flow;
            out.push_back(line);
            head = p;
        }
    }
    return out;
}

}  // namespace

void mergeGapLines(PlannedLayer& layer, int extruder, const std::function<GapMergeParams(int)>& params) {
    std::vector<PlanStep>& steps = layer.steps;
    bool any = false;
    for (const PlanStep& step : steps)
        any = any || (step.kind == PlanStep::Kind::Extrude && step.mergeable);
    if (!any)
        return;
    std::vector<bool> dropped(steps.size(), false);
    std::vector<std::optional<Merged>> merged_at(steps.size());
    std::size_t from = 0;
    Point2 head{0, 0};
    for (std::size_t s = 0; s <= steps.size(); ++s) {
        if (s < steps.size() && !endsExtruderPlan(steps[s].kind))
            continue;
        const std::vector<Unit> units = unitsOf(steps, from, s);
        Walk w{steps, units, params(extruder), std::vector<std::optional<Merged>>(units.size()), {}, 0};
        w.dropped.assign(steps.size(), false);
        walk(w, head);
        for (std::size_t k = 0; k < units.size(); ++k) {
            if (w.merged[k])
                merged_at[units[k].last] = std::move(w.merged[k]);
        }
        for (std::size_t d = 0; d < steps.size(); ++d)
            dropped[d] = dropped[d] || w.dropped[d];
        if (!units.empty())
            head = steps[units.back().last].to;
        if (s < steps.size() && steps[s].kind == PlanStep::Kind::SetExtruder)
            extruder = steps[s].extruder;
        from = s + 1;
    }
    const bool changed =
        std::any_of(merged_at.begin(), merged_at.end(), [](const auto& m) { return m.has_value(); }) ||
        std::find(dropped.begin(), dropped.end(), true) != dropped.end();
    if (changed)  // the planner's serial path: most layers merge nothing, and copying their steps costs
        steps = rebuilt(std::move(steps), dropped, merged_at);
}

}  // namespace mixengine
