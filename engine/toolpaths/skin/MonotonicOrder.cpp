#include "toolpaths/skin/MonotonicOrder.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace mixengine {
namespace {

/// The monotonic direction as CuraEngine holds it: a vector of length 1000 µm in integers.
constexpr double kVectorLength = 1000;

struct Projected {
    std::size_t index = 0;
    long long low = 0, high = 0;                ///< projections of the ends on the direction
    long long across_low = 0, across_high = 0;  ///< and on its perpendicular
};

long long dot(const Point2& p, const Point2& v) {
    return p.X * v.X + p.Y * v.Y;
}

Projected project(const Path& line, std::size_t index, const Point2& along, const Point2& across) {
    const long long a = dot(line.front(), along), b = dot(line.back(), along);
    const long long c = dot(line.front(), across), d = dot(line.back(), across);
    return {index, std::min(a, b), std::max(a, b), std::min(c, d), std::max(c, d)};
}

bool overlapAcross(const Projected& mine, const Projected& theirs) {
    return (mine.across_low >= theirs.across_low && mine.across_low <= theirs.across_high) ||
           (mine.across_high >= theirs.across_low && mine.across_high <= theirs.across_high) ||
           (theirs.across_low >= mine.across_low && theirs.across_high <= mine.across_high);
}

/// Positions (in `sorted`) of the later lines adjacent to sorted[i].
std::vector<std::size_t> adjacentLater(const std::vector<Projected>& sorted, std::size_t i, long long reach) {
    std::vector<std::size_t> found;
    const Projected& mine = sorted[i];
    for (std::size_t j = i + 1; j < sorted.size(); ++j) {
        const Projected& theirs = sorted[j];
        if (theirs.low - mine.high > reach || mine.low - theirs.high > reach)
            break;
        if (overlapAcross(mine, theirs))
            found.push_back(j);
    }
    return found;
}

struct Links {
    std::vector<std::size_t> next;  ///< position of the line each line leads on to; npos = none
    std::vector<bool> starts;       ///< starts a run
};

constexpr std::size_t kNone = static_cast<std::size_t>(-1);

Links linkLines(const std::vector<Projected>& sorted, long long reach) {
    Links links{std::vector<std::size_t>(sorted.size(), kNone), std::vector<bool>(sorted.size(), false)};
    std::vector<bool> reached(sorted.size(), false);
    for (std::size_t i = 0; i < sorted.size(); ++i) {
        if (!reached[i])
            links.starts[i] = true;
        const std::vector<std::size_t> adjacent = adjacentLater(sorted, i, reach);
        if (adjacent.size() == 1) {
            links.next[i] = adjacent[0];
            if (reached[adjacent[0]])
                links.starts[adjacent[0]] = true;  // reached from two lines: a run must start there
            reached[adjacent[0]] = true;
        } else {
            for (std::size_t j : adjacent)
                links.starts[j] = true;
        }
    }
    return links;
}

}  // namespace

Paths monotonicOrder(Paths lines, double angle_degrees, coord_um max_adjacent_um) {
    const double radians = angle_degrees * std::numbers::pi / 180.0;
    const Point2 along{static_cast<coord_um>(-std::cos(radians) * kVectorLength),
                       static_cast<coord_um>(std::sin(radians) * kVectorLength)};
    const Point2 across{-along.Y, along.X};
    std::vector<Projected> sorted;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        if (lines[i].size() >= 2)
            sorted.push_back(project(lines[i], i, along, across));
    }
    std::stable_sort(sorted.begin(), sorted.end(),
                     [](const Projected& a, const Projected& b) { return a.low < b.low; });
    const Links links = linkLines(sorted, max_adjacent_um * static_cast<long long>(kVectorLength));

    std::vector<std::size_t> run_starts;
    for (std::size_t i = 0; i < sorted.size(); ++i) {
        if (links.starts[i])
            run_starts.push_back(i);
    }
    std::stable_sort(run_starts.begin(), run_starts.end(), [&](std::size_t a, std::size_t b) {
        const Projected &x = sorted[a], &y = sorted[b];
        return x.low != y.low ? x.low < y.low : x.high < y.high;
    });
    Paths ordered;
    ordered.reserve(sorted.size());
    for (std::size_t start : run_starts) {
        std::size_t at = start;
        do {
            ordered.push_back(std::move(lines[sorted[at].index]));
            at = links.next[at];
        } while (at != kNone && !links.starts[at]);
    }
    return ordered;
}

}  // namespace mixengine
