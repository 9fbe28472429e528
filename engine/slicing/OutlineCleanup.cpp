#include "slicing/OutlineCleanup.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <optional>

#include "common/ParallelFor.h"
#include "geometry/Clip.h"
#include "geometry/Point.h"

namespace mixengine {
namespace {

// The simplification works in 64-bit integers as CuraEngine 4.13's does (its truncating divisions
// decide which vertices go, so doubles would keep or drop others).

std::int64_t squaredUm2(const Point2& a, const Point2& b) {
    const std::int64_t dx = b.X - a.X, dy = b.Y - a.Y;
    return dx * dx + dy * dy;
}

/// Length rounded down to whole microns.
std::int64_t truncatedLengthUm(const Point2& a, const Point2& b) {
    return static_cast<std::int64_t>(std::sqrt(static_cast<double>(squaredUm2(a, b))));
}

/// Twice the signed area of the triangle (origin, a, b): one term of the shoelace sum.
std::int64_t shoelaceTerm(const Point2& a, const Point2& b) {
    return a.X * b.Y - a.Y * b.X;
}

/// v², wrapping on overflow as the 64-bit product does in CuraEngine (only for huge cut-off areas).
std::int64_t wrappingSquare(std::int64_t v) {
    const auto u = static_cast<std::uint64_t>(v);
    return static_cast<std::int64_t>(u * u);
}

/// Distance from p to the infinite line through a and b, rounded down: twice the triangle's area
/// over the base length rounded down (a = b: the distance to a, rounded down).
std::int64_t truncatedDistanceToLineUm(const Point2& p, const Point2& a, const Point2& b) {
    const std::int64_t base = truncatedLengthUm(a, b);
    if (base == 0)
        return truncatedLengthUm(a, p);
    const std::int64_t twice_area = std::llabs((p.X - b.X) * (p.Y - a.Y) + (a.X - p.X) * (p.Y - b.Y));
    return static_cast<std::int64_t>(static_cast<double>(twice_area) / static_cast<double>(base));
}

/// Squared distance from p to the line through a and b: |ap|² minus the squared projection
/// (rounded down), not below 0; a projection too long to square goes through the distance.
std::int64_t squaredDistanceToLineUm2(const Point2& p, const Point2& a, const Point2& b) {
    constexpr std::int64_t kLargestSquarable = 3'037'000'499;
    const std::int64_t base_sq = squaredUm2(a, b);
    const std::int64_t ap_sq = squaredUm2(a, p);
    if (base_sq == 0)
        return ap_sq;
    const std::int64_t projection = (b.X - a.X) * (p.X - a.X) + (b.Y - a.Y) * (p.Y - a.Y);
    if (std::llabs(projection) > kLargestSquarable) {
        const std::int64_t distance = truncatedDistanceToLineUm(p, a, b);
        return distance <= kLargestSquarable ? distance * distance : INT64_MAX;
    }
    return std::max<std::int64_t>(0, ap_sq - projection * projection / base_sq);
}

/// Where the lines a–b and c–d meet, as CuraEngine 4.13 computes it (in doubles, truncated), which
/// includes its Y term: the Y coordinate comes out as c1 · (a1 − a2) / determinant with the lines
/// written a1·x + b1·y = c1 and a2·x + b2·y = c2. None when parallel or beyond ±2³¹.
std::optional<Point2> curaLineIntersection(const Point2& a, const Point2& b, const Point2& c,
                                           const Point2& d) {
    const double a1 = double(b.Y - a.Y), b1 = double(a.X - b.X);
    const double a2 = double(d.Y - c.Y), b2 = double(c.X - d.X);
    const double determinant = a1 * b2 - a2 * b1;
    if (determinant == 0)
        return std::nullopt;
    const double c1 = a1 * double(a.X) + b1 * double(a.Y);
    const double c2 = a2 * double(c.X) + b2 * double(c.Y);
    const auto x = static_cast<std::int64_t>((b2 * c1 - b1 * c2) / determinant);
    const auto y = static_cast<std::int64_t>((a1 * c1 - a2 * c1) / determinant);
    if (std::llabs(x) > INT32_MAX || std::llabs(y) > INT32_MAX)
        return std::nullopt;
    return Point2{x, y};
}

/// The walk of simplifyLoop: the kept vertices so far, the last two of them, and twice the
/// signed area between the path of dropped vertices since `previous` and the origin.
struct SimplifyWalk {
    std::int64_t resolution_sq;
    std::int64_t deviation_sq;
    Path kept;
    Point2 previous, before_previous;
    std::int64_t swept = 0;

    /// A short segment to `current` followed by a long one: moving `current` to where the
    /// segment before `previous` and the next one meet keeps both directions (a sharper corner)
    /// and lets `previous` go — when that point stays within the deviation and the resolution.
    void moveCorner(Point2& current, const Point2& next) {
        const std::optional<Point2> meet = curaLineIntersection(before_previous, previous, current, next);
        if (!meet || squaredDistanceToLineUm2(*meet, previous, current) > deviation_sq ||
            squaredUm2(*meet, previous) > resolution_sq || squaredUm2(*meet, next) > resolution_sq)
            return;
        current = *meet;
        if (!kept.empty()) {
            kept.pop_back();
            previous = before_previous;
        }
    }

    /// Whether `current` goes (its segment from `previous` is finer than the printer follows);
    /// may move it instead (moveCorner).
    bool drops(Point2& current, const Point2& next) {
        const std::int64_t length_sq = squaredUm2(previous, current);
        if (length_sq < 25)
            return true;  // under 5 µm: always
        const std::int64_t base_sq = squaredUm2(previous, next);
        if (base_sq == 0)
            return true;                                                // there and back
        const std::int64_t cut = swept + shoelaceTerm(next, previous);  // the area the shortcut cuts off
        const std::int64_t height_sq = wrappingSquare(cut) / base_sq;   // of a triangle on the shortcut
        if (height_sq <= 1 && truncatedDistanceToLineUm(current, previous, next) <= 1)
            return true;  // collinear
        if (length_sq >= resolution_sq || height_sq > deviation_sq)
            return false;
        if (squaredUm2(current, next) <= resolution_sq)
            return true;
        moveCorner(current, next);
        return false;
    }
};

}  // namespace

bool loopShorterThan(const Path& loop, coord_um length_um) {
    std::int64_t sum = 0;
    for (std::size_t i = 0; i < loop.size(); ++i) {
        sum += truncatedLengthUm(loop[i == 0 ? loop.size() - 1 : i - 1], loop[i]);
        if (sum >= length_um)
            return false;
    }
    return true;
}

Path simplifyLoop(const Path& loop, coord_um maximum_resolution_um, coord_um maximum_deviation_um) {
    const std::size_t n = loop.size();
    if (n < 3)
        return {};
    if (n == 3)
        return loop;
    SimplifyWalk walk{maximum_resolution_um * maximum_resolution_um,
                      maximum_deviation_um * maximum_deviation_um,
                      {},
                      loop[n - 1],
                      loop[n - 2]};
    walk.swept = shoelaceTerm(walk.previous, loop[0]);
    for (std::size_t i = 0; i < n; ++i) {
        Point2 current = loop[i];
        // The last vertex is weighed against the first one kept (the loop closes there).
        const Point2 next = i + 1 < n ? loop[i + 1] : (walk.kept.size() > 1 ? walk.kept.front() : loop[0]);
        const std::int64_t term = shoelaceTerm(current, next);
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

void removeHoles(std::vector<SlicedLayer>& layers, int threads) {
    parallelFor(layers.size(), threads, [&](std::size_t i) {
        Paths& outlines = layers[i].outlines;
        std::erase_if(outlines, [](const Path& loop) { return !counterClockwise(loop); });
        outlines = clipAreas(outlines, {}, ClipOp::Union, FillRule::NonZero);
    });
}

Paths simplifyLoops(Paths loops, coord_um maximum_resolution_um, coord_um maximum_deviation_um) {
    if (maximum_resolution_um <= 0 && maximum_deviation_um <= 0)
        return loops;
    for (Path& loop : loops)
        loop = simplifyLoop(loop, maximum_resolution_um, maximum_deviation_um);
    std::erase_if(loops, [](const Path& loop) { return loop.size() < 3; });
    return loops;
}

}  // namespace mixengine
