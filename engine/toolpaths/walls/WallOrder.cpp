#include "toolpaths/walls/WallOrder.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/PolygonOps.h"

namespace mixengine {
namespace {

constexpr std::size_t kSamples = 16;

double pointToSegmentUm(const Point2& p, const Point2& a, const Point2& b) {
    const double dx = double(b.X - a.X), dy = double(b.Y - a.Y);
    const double px = double(p.X - a.X), py = double(p.Y - a.Y);
    const double length2 = dx * dx + dy * dy;
    const double t = length2 > 0 ? std::clamp((px * dx + py * dy) / length2, 0.0, 1.0) : 0.0;
    return std::hypot(px - t * dx, py - t * dy);
}

double pointToLoopUm(const Point2& p, const Path& loop) {
    double best = std::numeric_limits<double>::max();
    for (std::size_t i = 0; i < loop.size(); ++i)
        best = std::min(best, pointToSegmentUm(p, loop[i], loop[(i + 1) % loop.size()]));
    return best;
}

/// The mean distance of up to kSamples vertices of `child`, spread along it, to `parent`.
double meanDistanceUm(const Path& child, const Path& parent) {
    const std::size_t step = std::max<std::size_t>(1, child.size() / kSamples);
    double sum = 0;
    std::size_t count = 0;
    for (std::size_t i = 0; i < child.size(); i += step, ++count)
        sum += pointToLoopUm(child[i], parent);
    return count > 0 ? sum / double(count) : std::numeric_limits<double>::max();
}

bool holds(const Box2& outer, coord_um margin, const Box2& inner) {
    return outer.left - margin <= inner.left && outer.top - margin <= inner.top &&
           outer.right + margin >= inner.right && outer.bottom + margin >= inner.bottom;
}

/// The loop of `parents` that `child` runs closest along (candidates by bounds first).
std::size_t parentOf(const Path& child, const Paths& parents, const std::vector<Box2>& bounds,
                     coord_um step_um) {
    const Box2 box = boundsOf({child});
    std::size_t candidates = 0, only = 0;
    for (std::size_t j = 0; j < parents.size() && candidates < 2; ++j) {
        if (holds(bounds[j], 2 * step_um, box))
            ++candidates, only = j;
    }
    if (candidates == 1)  // the usual case: no distances to weigh
        return only;
    std::size_t best = 0;
    double best_distance = std::numeric_limits<double>::max();
    for (bool filtered : {true, false}) {
        for (std::size_t j = 0; j < parents.size(); ++j) {
            if (filtered && !holds(bounds[j], 2 * step_um, box))
                continue;
            const double d = meanDistanceUm(child, parents[j]);
            if (d < best_distance)
                best = j, best_distance = d;
        }
        if (best_distance < std::numeric_limits<double>::max())
            break;
    }
    return best;
}

}  // namespace

std::vector<std::vector<std::size_t>> wallFamilies(const std::vector<Paths>& levels,
                                                   const std::vector<coord_um>& level_step_um) {
    std::vector<std::vector<std::size_t>> families(levels.size());
    if (levels.empty())
        return families;
    for (std::size_t i = 0; i < levels[0].size(); ++i)
        families[0].push_back(i);
    for (std::size_t k = 1; k < levels.size(); ++k) {
        const Paths& parents = levels[k - 1];
        std::vector<Box2> bounds;
        for (const Path& parent : parents)
            bounds.push_back(boundsOf({parent}));
        const coord_um step = k < level_step_um.size() ? level_step_um[k] : 0;
        for (const Path& child : levels[k]) {
            families[k].push_back(parents.empty() ? 0
                                                  : families[k - 1][parentOf(child, parents, bounds, step)]);
        }
    }
    return families;
}

}  // namespace mixengine
