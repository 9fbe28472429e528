#include "planning/Coasting.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace mixengine {
namespace {

/// CuraEngine's vSize: the length of a vector, truncated to whole microns.
coord_um lengthUm(const Point2& a, const Point2& b) {
    const double dx = double(a.X - b.X), dy = double(a.Y - b.Y);
    return static_cast<coord_um>(std::sqrt(dx * dx + dy * dy));
}

/// A volume spread over a line `width_um` wide and `thickness_um` high, as CuraEngine rounds it:
/// the volume in whole µm²·mm, divided (whole numbers) by the thickness, then by the width.
coord_um spreadDistanceUm(double volume_mm3, coord_um thickness_um, coord_um width_um) {
    const auto area = static_cast<coord_um>(std::llround(volume_mm3 * 1e6));
    return (area / thickness_um) * 1000 / width_um;
}

bool isMove(PlanStep::Kind kind) {
    return kind == PlanStep::Kind::Travel || kind == PlanStep::Kind::Extrude ||
           kind == PlanStep::Kind::LiftHead;
}

/// Whether the first move from step `from` on (in `steps`, else in `next`) is a travel.
bool travelFollows(const std::vector<PlanStep>& steps, std::size_t from, const PlannedLayer* next) {
    for (std::size_t k = from; k < steps.size(); ++k) {
        if (isMove(steps[k].kind))
            return steps[k].kind != PlanStep::Kind::Extrude;
    }
    if (next == nullptr)
        return false;
    for (const PlanStep& step : next->steps) {
        if (isMove(step.kind))
            return step.kind != PlanStep::Kind::Extrude;
    }
    return false;
}

/// Volume per micron of an extrusion from `from`; 0 for a move of no length.
double volumePerUm(const PlanStep& step, const Point2& from) {
    const double length = distanceUm(from, step.to);
    return length > 0 ? step.volume_mm3 / length : 0;
}

/// The end (exclusive) of the path that starts with the Extrude step `begin`, the head at `head`.
std::size_t pathEnd(const std::vector<PlanStep>& steps, std::size_t begin, Point2 head) {
    const PlanStep& first = steps[begin];
    const double rate = volumePerUm(first, head);
    head = first.to;
    std::size_t end = begin + 1;
    for (; end < steps.size(); ++end) {
        const PlanStep& step = steps[end];
        if (step.kind != PlanStep::Kind::Extrude || step.speed_mm_s != first.speed_mm_s ||
            step.width_um != first.width_um)
            break;
        const double r = volumePerUm(step, head);
        if (r > 0 && rate > 0 && std::abs(r - rate) > 1e-9 * rate)
            break;
        head = step.to;
    }
    return end;
}

/// Where coasting starts on the path through `points` (the path's own points, not the head before
/// it): the index of the last point extruded to in full and the point the extrusion stops at; none
/// when it does not coast.
struct CoastStart {
    std::size_t last_full = 0;  ///< index into points
    Point2 at{};
};

/// The index k (1 …) of the first distance in `from_end` reaching `distance_um`; none if none does.
std::optional<std::size_t> firstReaching(const std::vector<coord_um>& from_end, coord_um distance_um) {
    for (std::size_t k = 1; k < from_end.size(); ++k) {
        if (from_end[k] >= distance_um)
            return k;
    }
    return std::nullopt;
}

std::optional<CoastStart> coastStart(const Path& points, coord_um coast_um, coord_um min_um) {
    const std::size_t n = points.size();
    std::vector<coord_um> from_end{0};  // [k]: along the path from points[n-1-k] to its end
    bool short_path = true;
    for (std::size_t back = 1; back < n; ++back) {
        from_end.push_back(from_end.back() + lengthUm(points[n - 1 - back], points[n - back]));
        if (from_end.back() >= min_um) {
            short_path = false;
            break;
        }
    }
    constexpr coord_um kMinConsideredUm = 100;
    if (from_end.back() < kMinConsideredUm)
        return std::nullopt;
    // a path shorter than the minimal distance coasts proportionally less
    const coord_um actual = short_path ? from_end.back() * coast_um / min_um : coast_um;
    const std::optional<std::size_t> index = firstReaching(from_end, actual);
    if (actual == 0 || !index)
        return std::nullopt;
    const std::size_t before = n - 1 - *index;
    const Point2& a = points[before];
    const Point2& b = points[before + 1];
    const coord_um residual = actual - from_end[*index - 1];
    const coord_um ab = lengthUm(a, b);
    const Point2 back =
        ab < 1 ? Point2{residual, 0} : Point2{(a.X - b.X) * residual / ab, (a.Y - b.Y) * residual / ab};
    return CoastStart{before, {b.X + back.X, b.Y + back.Y}};
}

/// The steps of the path steps[begin, end) with coasting, appended to `out`.
void coastPath(const std::vector<PlanStep>& steps, std::size_t begin, std::size_t end, coord_um thickness_um,
               const CoastingParams& params, std::vector<PlanStep>& out) {
    const PlanStep& first = steps[begin];
    std::optional<CoastStart> start;
    if (first.width_um > 0 && thickness_um > 0 && end - begin >= 2) {
        Path points;
        for (std::size_t k = begin; k < end; ++k)
            points.push_back(steps[k].to);
        const coord_um coast = spreadDistanceUm(params.volume_mm3, thickness_um, first.width_um);
        const coord_um min =
            spreadDistanceUm(params.volume_mm3 + params.min_volume_mm3, thickness_um, first.width_um);
        if (coast > 0 && min > 0)
            start = coastStart(points, coast, min);
    }
    if (!start) {
        out.insert(out.end(), steps.begin() + std::ptrdiff_t(begin), steps.begin() + std::ptrdiff_t(end));
        return;
    }
    const std::size_t stop = begin + start->last_full;  // the last step extruded in full
    out.insert(out.end(), steps.begin() + std::ptrdiff_t(begin), steps.begin() + std::ptrdiff_t(stop + 1));
    PlanStep partial = steps[stop + 1];
    const Point2 from = steps[stop].to;
    partial.volume_mm3 = volumePerUm(partial, from) * distanceUm(from, start->at);
    partial.to = start->at;
    out.push_back(partial);
    for (std::size_t k = stop + 1; k < end; ++k) {
        PlanStep coast;
        coast.kind = PlanStep::Kind::Travel;
        coast.to = steps[k].to;
        coast.speed_mm_s = steps[k].speed_mm_s * params.speed_ratio;
        out.push_back(coast);  // acceleration and jerk 0: the print values stay in force
    }
}

}  // namespace

CoastingParams coastingParams(const Settings& extruder) {
    CoastingParams p;
    p.enabled = extruder.boolean(key::coasting_enable);
    if (!p.enabled)
        return p;
    p.volume_mm3 = extruder.real(key::coasting_volume);
    p.min_volume_mm3 = extruder.real(key::coasting_min_volume);
    p.speed_ratio = extruder.ratio(key::coasting_speed);
    p.enabled = p.volume_mm3 > 0;
    return p;
}

void applyCoasting(PrintPlan& plan, const std::vector<CoastingParams>& per_extruder, int extruder) {
    if (std::none_of(per_extruder.begin(), per_extruder.end(),
                     [](const CoastingParams& p) { return p.enabled; }))
        return;  // nothing coasts: the steps stay as they are
    std::optional<Point2> head;
    for (std::size_t li = 0; li < plan.layers.size(); ++li) {
        PlannedLayer& layer = plan.layers[li];
        const PlannedLayer* next = li + 1 < plan.layers.size() ? &plan.layers[li + 1] : nullptr;
        std::vector<PlanStep> out;
        out.reserve(layer.steps.size());
        const std::vector<PlanStep>& steps = layer.steps;
        for (std::size_t i = 0; i < steps.size();) {
            const PlanStep& step = steps[i];
            if (step.kind == PlanStep::Kind::SetExtruder)
                extruder = step.extruder;
            if (step.kind != PlanStep::Kind::Extrude || !head) {
                out.push_back(step);
                if (isMove(step.kind))
                    head = step.to;
                ++i;
                continue;
            }
            const std::size_t end = pathEnd(steps, i, *head);
            const auto e = static_cast<std::size_t>(std::max(extruder, 0));
            const CoastingParams& params = per_extruder[std::min(e, per_extruder.size() - 1)];
            if (params.enabled && travelFollows(steps, end, next))
                coastPath(steps, i, end, layer.thickness, params, out);
            else
                out.insert(out.end(), steps.begin() + std::ptrdiff_t(i), steps.begin() + std::ptrdiff_t(end));
            head = steps[end - 1].to;
            i = end;
        }
        layer.steps = std::move(out);
    }
}

}  // namespace mixengine
