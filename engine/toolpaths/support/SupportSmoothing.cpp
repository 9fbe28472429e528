#include "toolpaths/support/SupportSmoothing.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <list>
#include <numbers>
#include <optional>

namespace mixengine {
namespace {

// The loop as a ring of points that can be cut and extended while walking it (CuraEngine's list
// polygon): stepping past either end wraps around.
using Ring = std::list<Point2>;
using At = Ring::iterator;

At after(Ring& ring, At at) {
    ++at;
    return at == ring.end() ? ring.begin() : at;
}

At before(Ring& ring, At at) {
    if (at == ring.begin())
        at = ring.end();
    return --at;
}

// Integer vector arithmetic as CuraEngine's (its Point helpers): lengths are truncated square roots,
// scaling divides in integers.
Point2 minus(const Point2& a, const Point2& b) {
    return {a.X - b.X, a.Y - b.Y};
}

Point2 plus(const Point2& a, const Point2& b) {
    return {a.X + b.X, a.Y + b.Y};
}

coord_um dot(const Point2& a, const Point2& b) {
    return a.X * b.X + a.Y * b.Y;
}

coord_um length2(const Point2& v) {
    return dot(v, v);
}

coord_um length(const Point2& v) {
    return static_cast<coord_um>(std::sqrt(static_cast<double>(length2(v))));
}

double lengthMm(const Point2& v) {
    const double x = static_cast<double>(v.X) / 1000.0, y = static_cast<double>(v.Y) / 1000.0;
    return std::sqrt(x * x + y * y);
}

/// v scaled to `len` (integer division); (len, 0) for a zero vector.
Point2 scaledTo(const Point2& v, coord_um len) {
    const coord_um own = length(v);
    if (own < 1)
        return {len, 0};
    return {v.X * len / own, v.Y * len / own};
}

/// a + (b − a) · t, each coordinate computed in float and truncated.
Point2 partWay(const Point2& a, const Point2& b, float t) {
    const Point2 d = minus(b, a);
    return plus(a, {static_cast<coord_um>(static_cast<float>(d.X) * t),
                    static_cast<coord_um>(static_cast<float>(d.Y) * t)});
}

/// Positive when p lies left of the line a → b (twice the signed triangle area).
coord_um leftOf(const Point2& p, const Point2& a, const Point2& b) {
    return (b.X - a.X) * (p.Y - a.Y) - (b.Y - a.Y) * (p.X - a.X);
}

/// Distance from p to the line through a and b, via the triangle's area (truncated).
coord_um distanceFromLine(const Point2& p, const Point2& a, const Point2& b) {
    const double ab = static_cast<double>(length(minus(b, a)));
    if (ab == 0)
        return length(minus(p, a));
    const coord_um twice_area = std::llabs((p.X - b.X) * (p.Y - a.Y) + (a.X - p.X) * (p.Y - b.Y));
    return static_cast<coord_um>(static_cast<double>(twice_area) / ab);
}

/// Squared distance from p to the line through a and b (through the area where the dot product's
/// square would overflow).
coord_um distance2FromLine(const Point2& p, const Point2& a, const Point2& b) {
    constexpr coord_um kSqrtMaxFloor = 3037000499;
    const Point2 ab = minus(b, a), ap = minus(p, a);
    const coord_um ab2 = length2(ab), ap2 = length2(ap);
    if (ab2 == 0)
        return ap2;
    const coord_um along = dot(ab, ap);
    if (along != 0 && std::llabs(along) > kSqrtMaxFloor) {
        const coord_um d = distanceFromLine(p, a, b);
        return d <= kSqrtMaxFloor ? d * d : std::numeric_limits<coord_um>::max();
    }
    return std::max<coord_um>(0, ap2 - along * along / ab2);
}

/// The point r on segment a → b at `dist` from p, the one nearer a when there are two; nullopt when
/// there is none.
std::optional<Point2> pointAtDistance(const Point2& p, const Point2& a, const Point2& b, coord_um dist) {
    const Point2 ab = minus(b, a), ap = minus(p, a);
    const coord_um ab_len = length(ab);
    const coord_um ax = ab_len < 50 ? dot(scaledTo(ab, 1000), ap) / 1000 : dot(ab, ap) / ab_len;
    const coord_um px =
        static_cast<coord_um>(std::sqrt(static_cast<double>(std::max<coord_um>(0, length2(ap) - ax * ax))));
    if (px > dist)
        return std::nullopt;
    const coord_um xr = static_cast<coord_um>(std::sqrt(static_cast<double>(dist * dist - px * px)));
    coord_um ar = 0;
    if (ax <= 0) {
        ar = xr + ax;
    } else if (ax >= ab_len) {
        ar = ax - xr;
    } else {  // the foot of p lies on the segment: r on either side of it
        ar = ax - xr >= 0 ? ax - xr : ax + xr;
        if (ax - xr < 0 && ar >= ab_len)
            return std::nullopt;
    }
    if (ar < 0 || ar > ab_len)
        return std::nullopt;
    return plus(a, scaledTo(ab, ar));
}

/// Inserts p between `first` and `second` (neighbours) unless it is one of them; the point's place.
At insertBetween(Ring& ring, At first, At second, const Point2& p) {
    if (p == *first)
        return first;
    if (p == *second)
        return second;
    return ring.insert(second, p);
}

/// How the walk away from a corner stands in each direction (smoothComplex).
struct Walk {
    bool forward_blocked = false, forward_too_far = false;
    bool backward_blocked = false, backward_too_far = false;
    bool forwardDone() const { return forward_blocked || forward_too_far; }
    bool backwardDone() const { return backward_blocked || backward_too_far; }
};

/// One step of the walk: p2 one point on, or p0 one point back (the nearer to p1 first), unless that
/// would cut into the area or make the shortcut longer than allowed.
void walkStep(Ring& ring, const Point2& p1, coord_um length2_max, At& p0, At& p2, Walk& w) {
    const bool forward =
        !w.forwardDone() && (w.backwardDone() || length2(minus(*p2, p1)) < length2(minus(*p0, p1)));
    if (forward) {
        const At next = after(ring, p2);
        if (leftOf(*p2, *p0, *next) < 0)
            w.forward_blocked = true;
        else if (length2(minus(*next, *p0)) > length2_max)
            w.forward_too_far = true;
        else {
            p2 = next;
            w.backward_blocked = w.backward_too_far = false;
        }
        return;
    }
    const At prev = before(ring, p0);
    if (leftOf(*p0, *prev, *p2) < 0)
        w.backward_blocked = true;
    else if (length2(minus(*p2, *prev)) > length2_max)
        w.backward_too_far = true;
    else {
        p0 = prev;
        w.forward_blocked = w.forward_too_far = false;
    }
}

/// Walks p0 back and p2 on from the corner until the shortcut between them is as long as allowed
/// or blocked; false when the walk went all the way round (the whole loop goes).
bool walkAway(Ring& ring, const Point2& p1, coord_um len, At& p0, At& p2, Walk& w) {
    const coord_um len2 = len * len;
    while (true) {
        if (w.forwardDone() && w.backwardDone()) {
            if (!(w.forward_too_far && w.backward_too_far &&
                  length2(minus(*before(ring, p0), *after(ring, p2))) < len2))
                return true;
            p0 = before(ring, p0);
            p2 = after(ring, p2);
            w.forward_too_far = w.backward_too_far = false;
            continue;
        }
        walkStep(ring, p1, len2, p0, p2, w);
        if (before(ring, p0) == p2 || p0 == p2)
            return w.forward_too_far && w.backward_too_far;
    }
}

/// Both ends free: each moved part way along its next edge so that the shortcut is `len` long.
void extendBothEnds(Ring& ring, coord_um len, At& p0, At& p2) {
    const coord_um span = static_cast<coord_um>(std::sqrt(static_cast<double>(length2(minus(*p2, *p0)))));
    const At p0_back = before(ring, p0), p2_on = after(ring, p2);
    const coord_um span_next = length(minus(*p0_back, *p2_on));
    const float progress = static_cast<float>(std::min(
        1.0, (static_cast<double>(len - span) / 1000.0) / (static_cast<double>(span_next - span) / 1000.0)));
    const Point2 new_p0 = partWay(*p0, *p0_back, progress);
    p0 = insertBetween(ring, p0_back, p0, new_p0);
    const Point2 new_p2 = partWay(*p2, *p2_on, progress);
    p2 = insertBetween(ring, p2, p2_on, new_p2);
}

/// One end blocked: the free end (`moving`, with `beyond` the point after it away from the corner)
/// goes to where the shortcut from `fixed` is `len` long.
void extendOneEnd(Ring& ring, coord_um len, const At& fixed, At& moving, At beyond, bool moving_is_p0) {
    const std::optional<Point2> end = pointAtDistance(*fixed, *moving, *beyond, len);
    if (end)
        moving = moving_is_p0 ? insertBetween(ring, beyond, moving, *end)
                              : insertBetween(ring, moving, beyond, *end);
    else if (length(minus(*fixed, *beyond)) < length2(minus(*fixed, *moving)))  // (sic: CuraEngine's test)
        moving = beyond;
}

/// A notch whose neighbours are closer than the shortcut: walk away from it (walkAway), set the
/// shortcut's ends and cut out what lies between them; true when the whole loop goes.
bool smoothComplex(Ring& ring, const Point2& p1, coord_um len, At& p0, At& p2) {
    Walk w;
    if (!walkAway(ring, p1, len, p0, p2, w))
        return true;
    const coord_um span2 = length2(minus(*p2, *p0));
    if (std::llabs(span2 - len * len) < len * 10) {
        // about the shortcut's length already
    } else if (!w.backward_blocked && !w.forward_blocked) {
        extendBothEnds(ring, len, p0, p2);
    } else if (!w.backward_blocked) {
        extendOneEnd(ring, len, p2, p0, before(ring, p0), true);
    } else if (!w.forward_blocked) {
        extendOneEnd(ring, len, p0, p2, after(ring, p2), false);
    }
    while (after(ring, p0) != p2)
        ring.erase(after(ring, p0));
    return false;
}

/// A notch whose neighbours are at least the shortcut apart: the corner replaced by a shortcut.
void smoothSimple(Ring& ring, At p0, At p1, At p2, coord_um len, float cos_angle) {
    const Point2 v10 = minus(*p0, *p1), v12 = minus(*p2, *p1), v02 = minus(*p2, *p0);
    if (length2(v02) <= len * (len + 10) ||
        (cos_angle > 0.9999 && distance2FromLine(*p2, *p0, *p1) < 20 * 20)) {
        ring.erase(p1);  // the corner alone goes
        return;
    }
    const double half_angle = std::acos(static_cast<double>(cos_angle)) / 2;
    const coord_um leg = static_cast<coord_um>(static_cast<double>(len / 2) / std::sin(half_angle));
    if (leg * leg < length2(v10) && leg * leg < length2(v12)) {
        const Point2 a = plus(*p1, scaledTo(v10, leg)), b = plus(*p1, scaledTo(v12, leg));
        insertBetween(ring, p0, p1, a);
        insertBetween(ring, p1, p2, b);
    } else if (length2(v12) < length2(v10)) {
        if (const std::optional<Point2> a = pointAtDistance(*p2, *p1, *p0, len))
            insertBetween(ring, p0, p1, *a);
    } else if (const std::optional<Point2> b = pointAtDistance(*p0, *p1, *p2, len)) {
        insertBetween(ring, p1, p2, *b);
    }
    ring.erase(p1);
}

/// Points within 10 µm of the next one go, looked at from the ring's start until the walk comes
/// back to the (possibly new) start.
void dropNearDuplicates(Ring& ring) {
    At at = ring.begin();
    do {
        if (ring.size() < 2)
            return;
        const At next = after(ring, at);
        if (length2(minus(*at, *next)) < 10 * 10)
            ring.erase(at);
        at = next;
    } while (at != ring.begin());
}

/// The cosine of the corner at p1 in CuraEngine's precision (float, from millimetres).
float cornerCosine(const Point2& v10, const Point2& v12) {
    const double product_mm2 = static_cast<double>(dot(v10, v12)) / 1000.0 / 1000.0;
    return static_cast<float>(product_mm2 / lengthMm(v10) / lengthMm(v12));
}

/// The loop smoothed; nullopt when it goes altogether.
std::optional<Path> smoothLoop(const Path& loop, float cos_max, coord_um len) {
    Ring ring(loop.begin(), loop.end());
    dropNearDuplicates(ring);
    At p1 = ring.begin();
    do {
        if (ring.size() < 3)
            break;
        At p0 = before(ring, p1), p2 = after(ring, p1);
        const Point2 v10 = minus(*p0, *p1), v12 = minus(*p2, *p1);
        const float cos_angle = cornerCosine(v10, v12);
        if (!(cos_angle > cos_max && leftOf(*p1, *p0, *p2) > 0)) {
            p1 = after(ring, p1);
            continue;
        }
        if (length2(minus(*p2, *p0)) >= len * len)
            smoothSimple(ring, p0, p1, p2, len, cos_angle);
        else if (smoothComplex(ring, Point2(*p1), len, p0, p2))  // a copy: the corner may go
            return std::nullopt;
        p1 = p2;
    } while (p1 != ring.begin());
    return Path(ring.begin(), ring.end());
}

}  // namespace

Paths smoothOutward(const Paths& areas, double max_angle_degrees, coord_um shortcut_um) {
    if (shortcut_um <= 0)
        return areas;
    const float cos_max = static_cast<float>(std::cos(max_angle_degrees / 180 * std::numbers::pi));
    Paths out;
    for (const Path& loop : areas) {
        if (loop.size() < 3)
            continue;
        if (loop.size() == 3) {
            out.push_back(loop);
            continue;
        }
        std::optional<Path> smooth = smoothLoop(loop, cos_max, shortcut_um);
        if (smooth && smooth->size() >= 3)
            out.push_back(std::move(*smooth));
    }
    return out;
}

}  // namespace mixengine
