#include "slicing/OutlineCleanup.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "common/ParallelFor.h"
#include "geometry/Clip.h"
#include "geometry/Point.h"

namespace mixengine {
namespace {

double lengthUm(const Point2& a, const Point2& b) {
    return distanceUm(b, a);
}

double squaredUm2(const Point2& a, const Point2& b) {
    const double dx = double(b.X - a.X), dy = double(b.Y - a.Y);
    return dx * dx + dy * dy;
}

/// Twice the signed area of the triangle (origin, a, b): one term of the shoelace sum.
double shoelaceTerm(const Point2& a, const Point2& b) {
    return double(a.X) * double(b.Y) - double(a.Y) * double(b.X);
}

/// Squared distance from p to the infinite line through a and b (a ≠ b).
double squaredDistanceToLineUm2(const Point2& p, const Point2& a, const Point2& b) {
    const double cross = double(b.X - a.X) * double(p.Y - a.Y) - double(b.Y - a.Y) * double(p.X - a.X);
    return cross * cross / squaredUm2(a, b);
}

/// Where the infinite lines a–b and c–d meet; none when they are parallel.
std::optional<Point2> lineIntersection(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
    const double rx = double(b.X - a.X), ry = double(b.Y - a.Y);
    const double sx = double(d.X - c.X), sy = double(d.Y - c.Y);
    const double denominator = rx * sy - ry * sx;
    if (denominator == 0)
        return std::nullopt;
    const double t = (double(c.X - a.X) * sy - double(c.Y - a.Y) * sx) / denominator;
    return Point2{std::llround(double(a.X) + t * rx), std::llround(double(a.Y) + t * ry)};
}

/// The walk of simplifyLoop: the kept vertices so far, the last two of them, and twice the
/// signed area between the path of dropped vertices since `previous` and the origin.
struct SimplifyWalk {
    double resolution_sq;
    double deviation_sq;
    Path kept;
    Point2 previous, before_previous;
    double swept = 0;

    /// A short segment to `current` followed by a long one: moving `current` to where the
    /// segment before `previous` and the next one meet keeps both directions (a sharper corner)
    /// and lets `previous` go — when that point stays within the deviation and the resolution.
    bool moveCorner(Point2& current, const Point2& next) {
        const std::optional<Point2> meet = lineIntersection(before_previous, previous, current, next);
        if (!meet || squaredDistanceToLineUm2(*meet, previous, current) > deviation_sq ||
            squaredUm2(*meet, previous) > resolution_sq || squaredUm2(*meet, next) > resolution_sq)
            return false;
        current = *meet;
        if (!kept.empty()) {
            kept.pop_back();
            previous = before_previous;
        }
        return true;
    }

    /// Whether `current` goes (its segment from `previous` is finer than the printer follows);
    /// may move it instead (moveCorner).
    bool drops(Point2& current, const Point2& next) {
        if (squaredUm2(previous, current) < 25.0)
            return true;  // under 5 µm: always
        const double base_sq = squaredUm2(previous, next);
        if (base_sq == 0)
            return true;                                          // there and back
        const double cut = swept + shoelaceTerm(next, previous);  // the area the shortcut cuts off
        const double height_sq = cut * cut / base_sq;             // of a triangle on the shortcut
        if (height_sq <= 1.0 && squaredDistanceToLineUm2(current, previous, next) <= 1.0)
            return true;  // collinear
        if (squaredUm2(previous, current) >= resolution_sq || height_sq > deviation_sq)
            return false;
        if (squaredUm2(current, next) <= resolution_sq)
            return true;
        moveCorner(current, next);
        return false;
    }
};

}  // namespace

double loopLengthUm(const Path& loop) {
    double sum = 0;
    for (std::size_t i = 0; i < loop.size(); ++i)
        sum += lengthUm(loop[i], loop[(i + 1) % loop.size()]);
    return sum;
}

Path simplifyLoop(const Path& loop, coord_um maximum_resolution_um, coord_um maximum_deviation_um) {
    const std::size_t n = loop.size();
    if (n < 3)
        return {};
    if (n == 3)
        return loop;
    SimplifyWalk walk{double(maximum_resolution_um) * double(maximum_resolution_um),
                      double(maximum_deviation_um) * double(maximum_deviation_um),
                      {},
                      loop[n - 1],
                      loop[n - 2]};
    walk.swept = shoelaceTerm(walk.previous, loop[0]);
    for (std::size_t i = 0; i < n; ++i) {
        Point2 current = loop[i];
        // The last vertex is weighed against the first one kept (the loop closes there).
        const Point2 next = i + 1 < n ? loop[i + 1] : (walk.kept.size() > 1 ? walk.kept.front() : loop[0]);
        const double term = shoelaceTerm(current, next);
        walk.swept += term;
        if (walk.drops(current, next))
            continue;
        walk.swept = term;
        walk.before_previous = walk.previous;
        walk.previous = current;
        walk.kept.push_back(current);
    }
    return walk.kept;
}

void cleanOutlines(std::vector<SlicedLayer>& layers, const OutlineCleanupParams& params, int threads) {
    parallelFor(layers.size(), threads, [&](std::size_t i) {
        Paths& outlines = layers[i].outlines;
        std::erase_if(outlines, [&](const Path& p) {
            return loopLengthUm(p) < double(params.minimum_circumference_um);
        });
        if (params.maximum_resolution_um <= 0 && params.maximum_deviation_um <= 0)
            return;
        for (Path& loop : outlines)
            loop = simplifyLoop(loop, params.maximum_resolution_um, params.maximum_deviation_um);
        std::erase_if(outlines, [](const Path& loop) { return loop.size() < 3; });
    });
}

void removeHoles(std::vector<SlicedLayer>& layers, int threads) {
    parallelFor(layers.size(), threads, [&](std::size_t i) {
        Paths& outlines = layers[i].outlines;
        std::erase_if(outlines, [](const Path& loop) { return !counterClockwise(loop); });
        outlines = clipAreas(outlines, {}, ClipOp::Union, FillRule::NonZero);
    });
}

}  // namespace mixengine
