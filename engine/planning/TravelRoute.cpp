#include "planning/TravelRoute.h"

#include <cmath>

namespace mixengine {
namespace {

double lengthUm(Point2 from, const Path& points) {
    double sum = 0;
    for (const Point2& p : points) {
        sum += distanceUm(from, p);
        from = p;
    }
    return sum;
}

bool within(const Point2& a, const Point2& b, coord_um distance_um) {
    const double dx = double(a.X - b.X);
    const double dy = double(a.Y - b.Y);
    return dx * dx + dy * dy <= double(distance_um) * double(distance_um);
}

std::optional<TravelRoute> combed(const Point2& from, const Point2& to, const TravelParams& params) {
    const std::optional<Point2> start = params.comb->moveInside(from, params.comb_move_inside_um);
    const std::optional<Point2> end = params.comb->moveInside(to, params.comb_move_inside_um);
    if (!start || !end)
        return std::nullopt;
    std::optional<Path> route = params.comb->route(*start, *end);
    if (!route)
        return std::nullopt;
    TravelRoute travel{{}, false};
    if (*start != from)
        travel.points.push_back(*start);
    travel.points.insert(travel.points.end(), route->begin(), route->end());
    if (*end != to)
        travel.points.push_back(to);
    travel.points = thinTravel(from, travel.points, params.max_travel_resolution_um, *start != from);
    travel.retract = params.retraction_enable && params.combing_max_distance_um > 0 &&
                     lengthUm(from, travel.points) > double(params.combing_max_distance_um);
    travel.prime_before_last = travel.retract && *end != to;
    return travel;
}

/// A through-air travel to a mesh path whose end lies just outside the comb area: as CuraEngine's
/// comb, it goes to that end moved inside first and primes before the last move.
void enterBeforeTheWall(const Point2& to, const TravelParams& params, TravelRoute& travel) {
    if (!params.comb || !travel.retract)
        return;
    const std::optional<Point2> inside = params.comb->moveInside(to, params.comb_move_inside_um);
    if (!inside || *inside == to)
        return;
    travel.points.insert(travel.points.end() - 1, *inside);
    travel.prime_before_last = true;
}

}  // namespace

Path thinTravel(const Point2& from, const Path& points, coord_um resolution_um, bool first_kept) {
    if (resolution_um <= 0 || points.size() < 2)
        return points;
    Path kept;
    Point2 last = from;
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
        if ((i == 0 && first_kept) || !within(points[i], last, resolution_um)) {
            kept.push_back(points[i]);
            last = points[i];
        }
    }
    kept.push_back(points.back());
    return kept;
}

std::optional<Path> aroundParts(const CombBoundary& free, const Point2& from, const Point2& to) {
    const std::optional<Point2> start =
        free.inside(from) ? std::optional<Point2>(from) : free.entryToward(from, to);
    const std::optional<Point2> end =
        free.inside(to) ? std::optional<Point2>(to) : free.entryToward(to, from);
    if (!start || !end)
        return std::nullopt;
    std::optional<Path> middle = free.route(*start, *end);
    if (!middle)
        return std::nullopt;
    Path points;
    if (*start != from)
        points.push_back(*start);
    points.insert(points.end(), middle->begin(), middle->end());
    if (*end != to)
        points.push_back(to);
    return points;
}

TravelRoute planTravel(const Point2& from, const Point2& to, const TravelParams& params) {
    const bool long_travel = distanceUm(from, to) > static_cast<double>(params.retraction_min_travel_um);
    if (!long_travel)
        return {{to}, false};
    if (params.comb) {
        if (std::optional<TravelRoute> travel = combed(from, to, params))
            return *travel;
    }
    TravelRoute travel{{to}, params.retraction_enable};
    if (params.free && params.free->straightInside(from, to)) {
        // Clear of every part: support to support needs no retraction (limit_support_retractions).
        travel.retract = params.retraction_enable && !(params.limit_support_retractions && !params.comb);
        return travel;
    }
    if (params.free) {
        if (std::optional<Path> around = aroundParts(*params.free, from, to))
            travel.points = thinTravel(from, *around, params.max_travel_resolution_um, false);
    }
    enterBeforeTheWall(to, params, travel);
    return travel;
}

}  // namespace mixengine
