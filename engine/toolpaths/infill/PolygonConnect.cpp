#include "toolpaths/infill/PolygonConnect.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "geometry/PolygonOps.h"

namespace mixengine {
namespace {

double distanceUm(const Point2& a, const Point2& b) {
    return std::hypot(double(a.X - b.X), double(a.Y - b.Y));
}

/// A loop with the arc length at each vertex.
struct Measured {
    Path loop;
    std::vector<double> at;  ///< arc length from vertex 0 to vertex i
    double total = 0;
    Box2 box{0, 0, 0, 0};
};

Measured measured(Path loop) {
    Measured m;
    m.at.resize(loop.size());
    for (std::size_t i = 1; i < loop.size(); ++i)
        m.at[i] = m.at[i - 1] + distanceUm(loop[i - 1], loop[i]);
    m.total = loop.empty() ? 0 : m.at.back() + distanceUm(loop.back(), loop.front());
    m.box = boundsOf({loop});
    m.loop = std::move(loop);
    return m;
}

double wrapped(double s, double total) {
    const double r = std::fmod(s, total);
    return r < 0 ? r + total : r;
}

/// The point at arc length `s` (taken round the loop).
Point2 pointAt(const Measured& m, double s) {
    s = wrapped(s, m.total);
    const std::size_t n = m.loop.size();
    const std::size_t i =
        static_cast<std::size_t>(std::upper_bound(m.at.begin(), m.at.end(), s) - m.at.begin()) - 1;
    const Point2& a = m.loop[i];
    const Point2& b = m.loop[(i + 1) % n];
    const double length = (i + 1 < n ? m.at[i + 1] : m.total) - m.at[i];
    const double t = length > 0 ? (s - m.at[i]) / length : 0;
    return {a.X + static_cast<coord_um>(std::llround(t * double(b.X - a.X))),
            a.Y + static_cast<coord_um>(std::llround(t * double(b.Y - a.Y)))};
}

struct Nearest {
    double arc = 0;  ///< arc length of the nearest point on the loop
    double distance = 0;
};

Nearest nearestOn(const Measured& m, const Point2& q) {
    Nearest best{0, std::numeric_limits<double>::infinity()};
    const std::size_t n = m.loop.size();
    for (std::size_t i = 0; i < n; ++i) {
        const Point2& a = m.loop[i];
        const Point2& b = m.loop[(i + 1) % n];
        const double dx = double(b.X - a.X), dy = double(b.Y - a.Y);
        const double len2 = dx * dx + dy * dy;
        const double t =
            len2 > 0 ? std::clamp((double(q.X - a.X) * dx + double(q.Y - a.Y) * dy) / len2, 0.0, 1.0) : 0.0;
        const double d = std::hypot(double(a.X) + t * dx - double(q.X), double(a.Y) + t * dy - double(q.Y));
        if (d < best.distance)
            best = {m.at[i] + t * std::sqrt(len2), d};
    }
    return best;
}

/// The loop walked from arc length `from` for `length`, forwards or backwards: its end points and
/// the vertices between.
Path walk(const Measured& m, double from, double length, bool forward) {
    Path out{pointAt(m, from)};
    const std::size_t n = m.loop.size();
    std::vector<std::pair<double, std::size_t>> ahead;
    for (std::size_t i = 0; i < n; ++i) {
        const double d = wrapped(forward ? m.at[i] - from : from - m.at[i], m.total);
        if (d > 0 && d < length)
            ahead.emplace_back(d, i);
    }
    std::sort(ahead.begin(), ahead.end());
    for (const auto& [d, i] : ahead)
        out.push_back(m.loop[i]);
    out.push_back(pointAt(m, forward ? from + length : from - length));
    return out;
}

struct Bridge {
    std::size_t other = 0;
    double a = 0, a2 = 0;  ///< arc lengths on the loop joined
    double b = 0, b2 = 0;  ///< arc lengths on the other loop
    bool forward = true;   ///< a2 lies a line width after a (else before)
    double length = 0;
};

bool boxesNear(const Box2& a, const Box2& b, coord_um reach) {
    return a.left - reach <= b.right && b.left - reach <= a.right && a.top - reach <= b.bottom &&
           b.top - reach <= a.bottom;
}

/// The second bridge a line width along from the first (either way round), if close enough.
std::optional<Bridge> secondBridge(const Measured& from, const Measured& to, Bridge first, coord_um w) {
    const double reach = 1.5 * double(w);
    std::optional<Bridge> best;
    for (const bool forward : {true, false}) {
        const double a2 = first.a + (forward ? double(w) : -double(w));
        const Nearest b2 = nearestOn(to, pointAt(from, a2));
        const double along_other =
            std::min(wrapped(b2.arc - first.b, to.total), wrapped(first.b - b2.arc, to.total));
        if (b2.distance > reach || along_other > 2.0 * double(w) || along_other <= 0)
            continue;
        if (!best || b2.distance < best->length) {
            best = first;
            best->a2 = wrapped(a2, from.total);
            best->b2 = b2.arc;
            best->forward = forward;
            best->length = b2.distance;
        }
    }
    return best;
}

/// The nearest loop of `pool` that `current` can be joined to, with the two bridges.
std::optional<Bridge> findBridge(const Measured& current, const std::vector<Measured>& pool, coord_um w) {
    const double shortest = double(w - 10), longest = 1.5 * double(w);
    std::optional<Bridge> best;
    for (std::size_t k = 0; k < pool.size(); ++k) {
        if (!boxesNear(current.box, pool[k].box, static_cast<coord_um>(longest)))
            continue;
        for (std::size_t i = 0; i < current.loop.size(); ++i) {
            const Nearest near = nearestOn(pool[k], current.loop[i]);
            if (near.distance < shortest || near.distance > longest ||
                (best && near.distance >= best->length))
                continue;
            const std::optional<Bridge> both =
                secondBridge(current, pool[k], {k, current.at[i], 0, near.arc, 0, true, 0}, w);
            if (both) {
                best = both;
                best->length = near.distance;
            }
        }
    }
    return best;
}

/// The two loops joined along the bridge: `current` the long way from a2 to a, the other the long way
/// from b to b2.
Path joined(const Measured& current, const Measured& other, const Bridge& bridge) {
    const double cut = bridge.forward ? wrapped(bridge.a2 - bridge.a, current.total)
                                      : wrapped(bridge.a - bridge.a2, current.total);
    Path out = walk(current, bridge.a2, current.total - cut, bridge.forward);
    const double ahead = wrapped(bridge.b2 - bridge.b, other.total);
    const bool b2_ahead = ahead <= other.total / 2;  // the short way from b to b2 is forwards
    const double short_way = b2_ahead ? ahead : other.total - ahead;
    const Path rest = walk(other, bridge.b, other.total - short_way, !b2_ahead);
    out.insert(out.end(), rest.begin(), rest.end());
    return out;
}

}  // namespace

Paths connectLoops(const Paths& loops, coord_um line_width_um) {
    std::vector<Measured> pool;
    for (const Path& loop : loops) {
        Measured m = measured(loop);
        if (m.loop.size() >= 3 && m.total >= 2.0 * double(line_width_um))
            pool.push_back(std::move(m));
    }
    Paths out;
    while (!pool.empty()) {
        Measured current = std::move(pool.back());
        pool.pop_back();
        const std::optional<Bridge> bridge =
            pool.empty() ? std::nullopt : findBridge(current, pool, line_width_um);
        if (bridge)
            pool[bridge->other] = measured(joined(current, pool[bridge->other], *bridge));
        else
            out.push_back(std::move(current.loop));
    }
    return out;
}

}  // namespace mixengine
