#include "planning/PathOrder.h"

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

/// A combed travel (through the points of the comb route, no retraction) where the comb boundary
/// allows one, else a straight travel that retracts when longer than retraction_min_travel.
void appendTravel(const Point2& from, const Point2& to, const TravelParams& params,
                  std::vector<PlanStep>& steps) {
    PlanStep travel;
    travel.kind = PlanStep::Kind::Travel;
    travel.speed_mm_s = params.travel_speed_mm_s;
    const bool long_travel = distanceUm(from, to) > static_cast<double>(params.retraction_min_travel_um);
    if (long_travel && params.comb) {
        if (std::optional<Path> route = params.comb->route(from, to)) {
            for (const Point2& point : *route) {
                travel.to = point;
                steps.push_back(travel);
            }
            return;
        }
    }
    travel.to = to;
    travel.retract = params.retraction_enable && long_travel;
    steps.push_back(travel);
}

void emitPath(const ExtrusionPath& path, std::size_t start, const TravelParams& params, Point2& head,
              std::vector<PlanStep>& steps) {
    const Point2& first = path.points[start];
    appendTravel(head, first, params, steps);
    head = first;

    const std::size_t n = path.points.size();
    const bool reverse = !path.closed && start != 0;
    const std::size_t count = path.closed ? n : n - 1;
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
        head = to;
    }
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
    for (std::size_t placed = 0; placed < paths.size(); ++placed) {
        // Pick the nearest path by its nearest end (open lines) or its first vertex (loops, to keep
        // the search linear in the number of paths); the loop's best start is chosen afterwards.
        std::size_t best = paths.size();
        double best_distance = std::numeric_limits<double>::max();
        for (std::size_t i = 0; i < paths.size(); ++i) {
            if (done[i] || paths[i].points.size() < 2)
                continue;
            const double d = paths[i].closed ? distanceUm(head, paths[i].points.front())
                                             : std::min(distanceUm(head, paths[i].points.front()),
                                                        distanceUm(head, paths[i].points.back()));
            if (d < best_distance)
                best = i, best_distance = d;
        }
        std::size_t best_start = 0;
        if (best < paths.size())
            best_start = bestStart(paths[best], head, best_distance);
        if (best == paths.size())
            break;
        done[best] = true;
        if (feature != paths[best].feature) {
            PlanStep marker;
            marker.kind = PlanStep::Kind::SetFeature;
            marker.feature = paths[best].feature;
            steps.push_back(marker);
            feature = paths[best].feature;
        }
        emitPath(paths[best], best_start, params, head, steps);
    }
}

}  // namespace mixengine
