#include "planning/PathOrder.h"

#include "planning/BridgeWalls.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mixengine {
namespace {

/// Index of the best start vertex of `path` seen from `head`; for open paths 0 or size-1.
std::size_t bestStart(const ExtrusionPath& path, const Point2& head, double& best_distance) {
    best_distance = std::numeric_limits<double>::max();
    std::size_t best = 0;
    if (path.fixed_start) {
        best_distance = distanceUm(head, path.points.front());
        return 0;
    }
    if (path.closed) {
        for (std::size_t i = 0; i < path.points.size(); ++i) {
            double d = distanceUm(head, path.points[i]);
            if (d < best_distance)
                best_distance = d, best = i;
        }
        return best;
    }
    double to_front = distanceUm(head, path.points.front());
    double to_back = distanceUm(head, path.points.back());
    best_distance = std::min(to_front, to_back);
    return to_front <= to_back ? 0 : path.points.size() - 1;
}

/// The travel to `to` (planning/TravelRoute.h): retracting first when it must.
void appendTravel(const Point2& from, const Point2& to, const TravelParams& params,
                  std::vector<PlanStep>& steps) {
    const TravelRoute route = planTravel(from, to, params);
    PlanStep travel;
    travel.kind = PlanStep::Kind::Travel;
    travel.speed_mm_s = params.travel_speed_mm_s;
    travel.retract = route.retract;
    for (std::size_t i = 0; i < route.points.size(); ++i) {
        travel.to = route.points[i];
        travel.prime_first = route.prime_before_last && i + 1 == route.points.size();
        steps.push_back(travel);
        travel.retract = false;
    }
}

/// A travel (no retraction) from `head` along `points` for `distance_um`, as a nozzle wipe.
void appendWipe(const Path& points, coord_um distance_um, double speed_mm_s, Point2& head,
                std::vector<PlanStep>& steps) {
    double left = static_cast<double>(distance_um);
    for (const Point2& p : points) {
        const double d = distanceUm(head, p);
        if (d <= 0)
            continue;
        PlanStep wipe;
        wipe.kind = PlanStep::Kind::Travel;
        wipe.speed_mm_s = speed_mm_s;
        const double t = std::min(1.0, left / d);
        wipe.to = {head.X + static_cast<coord_um>(std::llround(double(p.X - head.X) * t)),
                   head.Y + static_cast<coord_um>(std::llround(double(p.Y - head.Y) * t))};
        steps.push_back(wipe);
        head = wipe.to;
        left -= d * t;
        if (left <= 0)
            return;
    }
}

/// The wipe after a path: along an outer wall loop from its start, or straight on past an infill line.
void appendPathWipe(const ExtrusionPath& path, std::size_t start, const TravelParams& params,
                    const Point2& before_end, Point2& head, std::vector<PlanStep>& steps) {
    if (path.closed && path.feature == Feature::WallOuter && params.wall_0_wipe_um > 0) {
        Path loop;
        for (std::size_t k = 1; k <= path.points.size(); ++k)
            loop.push_back(path.points[(start + k) % path.points.size()]);
        appendWipe(loop, params.wall_0_wipe_um, params.travel_speed_mm_s, head, steps);
    } else if (!path.closed && path.feature == Feature::Fill && params.infill_wipe_um > 0) {
        const double d = distanceUm(before_end, head);
        if (d <= 0)
            return;
        const double k = 1.0 + static_cast<double>(params.infill_wipe_um) / d;
        const Point2 beyond{
            before_end.X + static_cast<coord_um>(std::llround(double(head.X - before_end.X) * k)),
            before_end.Y + static_cast<coord_um>(std::llround(double(head.Y - before_end.Y) * k))};
        appendWipe({beyond}, params.infill_wipe_um, params.travel_speed_mm_s, head, steps);
    }
}

/// A spiral's rise (ExtrusionPath::spiral) at the end of each of its moves: one layer thickness over
/// the whole length, held over the flat tail, as CuraEngine 4.13 (rounded to microns).
std::vector<coord_um> spiralRises(const ExtrusionPath& path, coord_um thickness_um) {
    const std::size_t n = path.points.size();
    std::vector<coord_um> rises(n, 0);
    double total = 0;
    for (std::size_t k = 1; k < n; ++k)
        total += distanceUm(path.points[k - 1], path.points[k]);
    if (total <= 0)
        return rises;
    double length = 0;
    const std::size_t rising = n - std::min(path.spiral_flat_tail, n);
    for (std::size_t k = 1; k < n; ++k) {
        length += distanceUm(path.points[k - 1], path.points[k]);
        rises[k] = k < rising ? static_cast<coord_um>(std::llround(double(thickness_um) * length / total))
                              : rises[k - 1];
    }
    return rises;
}

void emitPath(const ExtrusionPath& path, std::size_t start, const TravelParams& params, Point2& head,
              std::vector<PlanStep>& steps) {
    if (path.closed)
        start = firstNonOverhanging(path, start);
    const Point2& first = path.points[start];
    appendTravel(head, first, params, steps);
    head = first;

    const std::size_t n = path.points.size();
    const bool reverse = !path.closed && start != 0;
    const std::size_t count = path.closed ? n : n - 1;
    const std::vector<coord_um> rises =
        path.spiral ? spiralRises(path, params.layer_thickness_um) : std::vector<coord_um>{};
    Point2 before_end = head;
    for (std::size_t k = 1; k <= count; ++k) {
        std::size_t index = path.closed ? (start + k) % n : (reverse ? n - 1 - k : k);
        const std::size_t from = path.closed ? (start + k - 1) % n : (reverse ? n - k : k - 1);
        const Point2& to = path.points[index];
        PlanStep extrude;
        extrude.kind = PlanStep::Kind::Extrude;
        extrude.to = to;
        extrude.speed_mm_s = path.speed_mm_s * overhangSpeedFactor(path, from, index);
        const double flow = path.flows.size() == n ? path.flows[index] : path.flow;
        extrude.width_um = path.width_um;
        extrude.mergeable = path.mergeable;
        extrude.volume_mm3 = extrusionVolumeMm3(head, to, path.width_um, params.layer_thickness_um, flow);
        extrude.rise_um = rises.empty() ? 0 : rises[index];
        steps.push_back(extrude);
        before_end = head;
        head = to;
    }
    appendPathWipe(path, start, params, before_end, head, steps);
}

/// Which paths the nearest-first search may pick: free paths and the first path of each sequence.
std::vector<bool> entryPaths(const std::vector<ExtrusionPath>& paths) {
    std::vector<bool> entry(paths.size(), true);
    std::vector<std::uint32_t> seen;
    for (std::size_t i = 0; i < paths.size(); ++i) {
        const std::uint32_t sequence = paths[i].sequence;
        if (sequence == 0 || paths[i].points.size() < 2)
            continue;
        entry[i] = std::find(seen.begin(), seen.end(), sequence) == seen.end();
        seen.push_back(sequence);
    }
    return entry;
}

/// The travel length the search compares: straight, or along the comb route when asked for and the
/// straight travel leaves the comb boundary (100 × straight without a route).
double orderDistance(const Point2& from, const Point2& to, const TravelParams& params) {
    const double straight = distanceUm(from, to);
    if (!params.comb_aware_order || params.comb == nullptr || params.comb->empty() || straight <= 0 ||
        params.comb->straightInside(from, to))
        return straight;
    const std::optional<Path> route = params.comb->route(from, to);
    if (!route)
        return straight * 100;
    double length = 0;
    Point2 at = from;
    for (const Point2& p : *route) {
        length += distanceUm(at, p);
        at = p;
    }
    return length;
}

/// The distance to a path's nearest end (open lines) or its first vertex (loops, to keep the search
/// linear in the number of paths); `bound`: the best so far (the comb route is only looked for when
/// the straight distance beats it).
double pathDistance(const ExtrusionPath& path, const Point2& from, const TravelParams& params, double bound) {
    double best = std::numeric_limits<double>::max();
    const Point2* ends[2] = {&path.points.front(), &path.points.back()};
    for (std::size_t e = 0; e < (path.closed ? 1U : 2U); ++e) {
        const double straight = distanceUm(from, *ends[e]);
        if (straight < std::min(best, bound))
            best = std::min(best, params.comb_aware_order ? orderDistance(from, *ends[e], params) : straight);
    }
    return best;
}

/// Index of the nearest path not done yet that may be picked (paths.size() when none is left).
std::size_t nearestEntry(const std::vector<ExtrusionPath>& paths, const std::vector<bool>& done,
                         const std::vector<bool>& entry, const Point2& from, const TravelParams& params) {
    std::size_t best = paths.size();
    double best_distance = std::numeric_limits<double>::max();
    for (std::size_t i = 0; i < paths.size(); ++i) {
        if (done[i] || !entry[i] || paths[i].points.size() < 2)
            continue;
        const double d = pathDistance(paths[i], from, params, best_distance);
        if (d < best_distance)
            best = i, best_distance = d;
    }
    return best;
}

/// The first path not done yet with at least two points (keep_order), paths.size() when none.
std::size_t nextInOrder(const std::vector<ExtrusionPath>& paths, const std::vector<bool>& done) {
    for (std::size_t i = 0; i < paths.size(); ++i) {
        if (!done[i] && paths[i].points.size() >= 2)
            return i;
    }
    return paths.size();
}

/// Where to start `path` seen from `from`: bestStart(), or for an open line with comb-aware order
/// the end nearer along the comb routes.
std::size_t startOf(const ExtrusionPath& path, const Point2& from, const TravelParams& params) {
    double unused = 0;
    if (!params.comb_aware_order || path.closed || path.fixed_start)
        return bestStart(path, from, unused);
    const bool front =
        orderDistance(from, path.points.front(), params) <= orderDistance(from, path.points.back(), params);
    return front ? 0 : path.points.size() - 1;
}

/// Whether the last ;TYPE: of `steps` was marked ;BRIDGE.
bool lastMarkedBridge(const std::vector<PlanStep>& steps) {
    for (auto it = steps.rbegin(); it != steps.rend(); ++it) {
        if (it->kind == PlanStep::Kind::SetFeature)
            return it->bridge;
    }
    return false;
}

/// Room in `steps` for `paths`: a move per point, and a travel and a marker or two per path; still
/// growing geometrically over a layer's calls.
void reserveSteps(const std::vector<ExtrusionPath>& paths, std::vector<PlanStep>& steps) {
    std::size_t expected = steps.size();
    for (const ExtrusionPath& path : paths)
        expected += path.points.size() + 4;
    if (expected > steps.capacity())
        steps.reserve(std::max(expected, 2 * steps.capacity()));
}

}  // namespace

void appendTravelTo(const Point2& from, const Point2& to, const TravelParams& params,
                    std::vector<PlanStep>& steps) {
    appendTravel(from, to, params, steps);
}

double extrusionVolumeMm3(const Point2& from, const Point2& to, coord_um width_um, coord_um thickness_um,
                          double flow) {
    const double length_mm = distanceUm(from, to) / kMicronsPerMm;
    return length_mm * micronsToMm(width_um) * micronsToMm(thickness_um) * flow;
}

void appendOrderedPaths(std::vector<ExtrusionPath> paths, const TravelParams& params, Point2& head,
                        std::optional<Feature>& feature, std::vector<PlanStep>& steps) {
    reserveSteps(paths, steps);
    std::vector<bool> done(paths.size(), false);
    const std::vector<bool> entry = entryPaths(paths);
    const bool keep_order = !paths.empty() && paths.front().keep_order;
    bool first = true;
    BridgeMarks marks{lastMarkedBridge(steps), -1};
    auto print = [&](std::size_t index) {
        const Point2 from = first && params.order_from ? *params.order_from : head;
        first = false;
        done[index] = true;
        const ExtrusionPath& path = paths[index];
        if (feature != path.feature || marks.bridge != path.bridge) {
            PlanStep marker;
            marker.kind = PlanStep::Kind::SetFeature;
            marker.feature = path.feature;
            marker.bridge = path.bridge;
            steps.push_back(marker);
            feature = path.feature;
            marks.bridge = path.bridge;
        }
        if (path.closed && path.bridge_wall && path.air_edges.size() == path.points.size()) {
            const Point2 before = head;
            const std::size_t start =
                emitBridgedWall(path, startOf(path, from, params), params, head, feature, marks, steps);
            appendPathWipe(path, start, params, before, head, steps);
            return;
        }
        markFan(path.fan_ratio, marks, steps);
        emitPath(path, startOf(path, from, params), params, head, steps);
    };
    for (;;) {
        const Point2 from = first && params.order_from ? *params.order_from : head;
        const std::size_t best =
            keep_order ? nextInOrder(paths, done) : nearestEntry(paths, done, entry, from, params);
        if (best == paths.size())
            break;
        print(best);
        const std::uint32_t sequence = paths[best].sequence;
        for (std::size_t j = best + 1; sequence != 0 && j < paths.size(); ++j) {
            if (!done[j] && paths[j].sequence == sequence && paths[j].points.size() >= 2)
                print(j);
        }
    }
    markFan(-1, marks, steps);  // the layer's fan again after a bridge
}

}  // namespace mixengine
