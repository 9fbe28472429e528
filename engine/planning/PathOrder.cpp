#include "planning/PathOrder.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mixengine {
namespace {

double distanceUm(const Point2& a, const Point2& b) {
    return std::hypot(static_cast<double>(a.X - b.X), static_cast<double>(a.Y - b.Y));
}

/// Index of the best start vertex of `path` seen from `head`; for open paths 0 or size-1.
std::size_t bestStart(const ExtrusionPath& path, const Point2& head, double& best_distance) {
    best_distance = std::numeric_limits<double>::max();
    std::size_t best = 0;
    if (path.closed && path.fixed_start) {
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
    for (const Point2& point : route.points) {
        travel.to = point;
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

void emitPath(const ExtrusionPath& path, std::size_t start, const TravelParams& params, Point2& head,
              std::vector<PlanStep>& steps) {
    const Point2& first = path.points[start];
    appendTravel(head, first, params, steps);
    head = first;

    const std::size_t n = path.points.size();
    const bool reverse = !path.closed && start != 0;
    const std::size_t count = path.closed ? n : n - 1;
    Point2 before_end = head;
    for (std::size_t k = 1; k <= count; ++k) {
        std::size_t index = path.closed ? (start + k) % n : (reverse ? n - 1 - k : k);
        const Point2& to = path.points[index];
        PlanStep extrude;
        extrude.kind = PlanStep::Kind::Extrude;
        extrude.to = to;
        extrude.speed_mm_s = path.speed_mm_s;
        extrude.volume_mm3 =
            extrusionVolumeMm3(head, to, path.width_um, params.layer_thickness_um, path.flow);
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

/// The nearest path that may be picked, by its nearest end (open lines) or its first vertex (loops,
/// to keep the search linear in the number of paths); paths.size() when none is left.
std::size_t nearestEntry(const std::vector<ExtrusionPath>& paths, const std::vector<bool>& done,
                         const std::vector<bool>& entry, const Point2& head) {
    std::size_t best = paths.size();
    double best_distance = std::numeric_limits<double>::max();
    for (std::size_t i = 0; i < paths.size(); ++i) {
        if (done[i] || !entry[i] || paths[i].points.size() < 2)
            continue;
        const double d = paths[i].closed ? distanceUm(head, paths[i].points.front())
                                         : std::min(distanceUm(head, paths[i].points.front()),
                                                    distanceUm(head, paths[i].points.back()));
        if (d < best_distance)
            best = i, best_distance = d;
    }
    return best;
}

}  // namespace

double extrusionVolumeMm3(const Point2& from, const Point2& to, coord_um width_um, coord_um thickness_um,
                          double flow) {
    const double length_mm = distanceUm(from, to) / kMicronsPerMm;
    return length_mm * micronsToMm(width_um) * micronsToMm(thickness_um) * flow;
}

void appendOrderedPaths(std::vector<ExtrusionPath> paths, const TravelParams& params, Point2& head,
                        std::optional<Feature>& feature, std::vector<PlanStep>& steps) {
    std::vector<bool> done(paths.size(), false);
    const std::vector<bool> entry = entryPaths(paths);
    auto print = [&](std::size_t index, std::size_t start) {
        done[index] = true;
        if (feature != paths[index].feature) {
            PlanStep marker;
            marker.kind = PlanStep::Kind::SetFeature;
            marker.feature = paths[index].feature;
            steps.push_back(marker);
            feature = paths[index].feature;
        }
        emitPath(paths[index], start, params, head, steps);
    };
    for (;;) {
        const std::size_t best = nearestEntry(paths, done, entry, head);
        if (best == paths.size())
            break;
        double unused = 0;
        print(best, bestStart(paths[best], head, unused));
        const std::uint32_t sequence = paths[best].sequence;
        for (std::size_t j = best + 1; sequence != 0 && j < paths.size(); ++j) {
            if (!done[j] && paths[j].sequence == sequence && paths[j].points.size() >= 2)
                print(j, bestStart(paths[j], head, unused));
        }
    }
}

}  // namespace mixengine
