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

/// CuraEngine's comb: how far travel ends are moved off a boundary (precision margin).
constexpr coord_um kOffBoundaryUm = 40;
/// Leaving points tried in order of preference before giving up.
constexpr std::size_t kExitsTried = 8;

void append(Path& points, const Path& more) {
    for (const Point2& p : more) {
        if (points.empty() || points.back() != p)
            points.push_back(p);
    }
}

/// Where a travel from `p` (inside the comb area) towards `toward` leaves p's island: the first of
/// the boundary's exits that p reaches combing; p itself when there is none.
Point2 leavingPoint(const CombBoundary& comb, const Point2& p, const Point2& toward, coord_um reach_um) {
    const std::vector<Point2> exits = comb.exitsToward(p, toward, reach_um, kOffBoundaryUm);
    for (std::size_t i = 0; i < exits.size() && i < kExitsTried; ++i) {
        if (comb.route(p, exits[i]))
            return exits[i];
    }
    return p;
}

/// Where the travel leaving at `in` gets out of the grown outlines: the point of `free` near both
/// `in` and the point `offset_um` from it towards `toward` (CuraEngine's findOutside); `in` itself
/// when it lies in free space already or no such point is near.
Point2 outsidePoint(const CombBoundary& free, const Point2& in, const Point2& toward, coord_um offset_um) {
    const double length = distanceUm(in, toward);
    if (length <= 0)
        return in;
    const double k = double(offset_um) / length;
    const Point2 preferred{in.X + static_cast<coord_um>(std::llround(double(toward.X - in.X) * k)),
                           in.Y + static_cast<coord_um>(std::llround(double(toward.Y - in.Y) * k))};
    // Minimising |x − in|² + |x − preferred|²/4 is minimising the distance to their weighted mean.
    const Point2 target{(4 * in.X + preferred.X) / 5, (4 * in.Y + preferred.Y) / 5};
    return free.moveInside(target, 3 * offset_um, kOffBoundaryUm).value_or(in);
}

/// The through-air middle of a travel between parts, after `in_start` and up to `in_end` (both
/// included unless equal to the way's last point): around the parts through `free` when that is
/// worth it; nothing when the way around cannot be found.
std::optional<Path> throughAir(const Point2& in_start, const Point2& in_end, const TravelParams& params) {
    const coord_um offset_um = params.comb_move_inside_um / 2 + params.avoid_distance_um;
    const double across = distanceUm(in_start, in_end);
    if (!params.free || across < 2.0 * double(offset_um))
        return Path{in_end};
    const Point2 out_start = outsidePoint(*params.free, in_start, in_end, offset_um);
    const Point2 out_end = outsidePoint(*params.free, in_end, out_start, offset_um);
    if (across < distanceUm(in_start, out_start) + distanceUm(in_end, out_end))
        return Path{in_end};
    if (!params.free->inside(out_start) || !params.free->inside(out_end))
        return std::nullopt;
    const std::optional<Path> around = params.free->route(out_start, out_end);
    if (!around)
        return std::nullopt;
    Path points{out_start};
    append(points, *around);
    append(points, Path{in_end});
    return points;
}

/// limit_support_retractions, as CuraEngine applies it to every combed travel: a travel between
/// two points outside the comb area (`moved_inside` false) that goes straight across (`air` is just
/// its end) does not retract unless, its ends lying close together, it crosses the grown outlines.
bool unretractedCrossing(const Point2& from, const Point2& to, bool moved_inside, const Path& air,
                         const TravelParams& params) {
    if (!params.limit_support_retractions || moved_inside || air.size() != 1 || !params.free)
        return false;
    const coord_um offset_um = params.comb_move_inside_um / 2 + params.avoid_distance_um;
    const bool close = distanceUm(from, to) < 2.0 * double(offset_um);
    return !close || !params.free->crossesBoundary(from, to);
}

/// A mesh travel that cannot comb (ends in different islands of the comb area, or outside it):
/// CuraEngine's Comb between parts (see the header).
std::optional<TravelRoute> betweenParts(const Point2& from, const Point2& to, const TravelParams& params) {
    const CombBoundary& comb = *params.comb;
    const coord_um reach_um = params.comb_move_inside_um / 2;
    const std::optional<Point2> start = comb.moveInside(from, params.comb_move_inside_um, kOffBoundaryUm);
    const std::optional<Point2> end = comb.moveInside(to, params.comb_move_inside_um, kOffBoundaryUm);
    const Point2 in_start = start ? leavingPoint(comb, *start, end.value_or(to), reach_um) : from;
    const Point2 in_end = end ? leavingPoint(comb, *end, in_start, reach_um) : to;
    Path points;
    if (start) {
        const std::optional<Path> inside = comb.route(*start, in_start);
        if (!inside)
            return std::nullopt;
        append(points, Path{*start});
        append(points, *inside);
    }
    const std::optional<Path> air = throughAir(in_start, in_end, params);
    if (!air)
        return std::nullopt;
    append(points, *air);
    if (end) {
        const std::optional<Path> inside = comb.route(in_end, *end);
        if (!inside)
            return std::nullopt;
        append(points, *inside);
        append(points, Path{to});
    }
    if (!points.empty() && points.front() == from)
        points.erase(points.begin());
    if (points.empty() || points.back() != to)
        points.push_back(to);
    TravelRoute travel{
        thinTravel(from, points, params.max_travel_resolution_um, start && *start != from),
        params.retraction_enable && !unretractedCrossing(from, to, start || end, *air, params)};
    travel.prime_before_last = travel.retract && end && *end != to;
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

namespace {

/// A travel too short to retract: straight, or where long enough the way CuraEngine's comb takes
/// (TravelRoute.h), never retracting.
TravelRoute shortTravel(const Point2& from, const Point2& to, const TravelParams& params) {
    TravelRoute travel{{to}, false};
    if (!params.comb || distanceUm(from, to) < static_cast<double>(params.short_comb_min_um))
        return travel;
    std::optional<TravelRoute> way = combed(from, to, params);
    if (!way)
        way = betweenParts(from, to, params);
    if (way)
        travel.points = std::move(way->points);
    return travel;
}

}  // namespace

TravelRoute planTravel(const Point2& from, const Point2& to, const TravelParams& params) {
    const bool long_travel = distanceUm(from, to) > static_cast<double>(params.retraction_min_travel_um);
    if (!long_travel)
        return shortTravel(from, to, params);
    if (params.comb) {
        if (std::optional<TravelRoute> travel = combed(from, to, params))
            return *travel;
        if (std::optional<TravelRoute> travel = betweenParts(from, to, params))
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
