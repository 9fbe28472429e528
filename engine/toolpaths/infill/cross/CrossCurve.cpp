#include "toolpaths/infill/cross/CrossCurve.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>

namespace mixengine {
namespace {

/// CuraEngine's integer vector length (truncated).
coord_um lengthOf(const Point2& v) {
    return static_cast<coord_um>(std::sqrt(double(v.X * v.X + v.Y * v.Y)));
}

/// `v` scaled to `length` (CuraEngine's normal(): integer arithmetic, truncated).
Point2 scaledTo(const Point2& v, coord_um length) {
    const coord_um size = lengthOf(v);
    if (size < 1)
        return {length, 0};
    return {v.X * length / size, v.Y * length / size};
}

Point2 exitMiddle(const SierpinskiNode& n) {
    const Point2& other = n.direction == CrossDirection::AcToAb ? n.a : n.c;
    return {(n.b.X + other.X) / 2, (n.b.Y + other.Y) / 2};
}

/// Where the cross_3d curve crosses `edge` at height z: a triangle wave of period 2·`period_um`.
Point2 crossingAt(const CrossEdge& edge, coord_um period_um, const Cross3dParams& p) {
    const Point2 along{edge.right.X - edge.left.X, edge.right.Y - edge.left.Y};
    const coord_um size = lengthOf(along);
    if (period_um <= 0)
        return edge.left;
    coord_um from_left = p.z_um % (2 * period_um);
    if (from_left > period_um)
        from_left = 2 * period_um - from_left;
    from_left = from_left * size / period_um;
    from_left = std::min(size - p.min_side_um, std::max(p.min_side_um, from_left));
    const Point2 step = scaledTo(along, from_left);
    return {edge.left.X + step.X, edge.left.Y + step.Y};
}

coord_um shortSide(const SierpinskiNode& n) {
    return lengthOf({n.c.X - n.a.X, n.c.Y - n.a.Y});
}

/// Whether the curve turns by a right angle at `at` (within `tolerance_um` of rounding).
bool rightAngle(const Point2& to_prev, const Point2& to_next, coord_um tolerance_um) {
    const coord_um dot = std::abs(to_prev.X * to_next.X + to_prev.Y * to_next.Y);
    return double(dot) < std::sqrt(double(lengthOf(to_prev) * lengthOf(to_next))) * double(tolerance_um);
}

Path withPockets(const Path& curve, const Cross3dParams& p) {
    const auto side = static_cast<coord_um>(double(p.pocket_um) * std::numbers::sqrt2 / 2);
    Path out;
    out.reserve(curve.size() * 3 / 2);
    Point2 prev = curve.back();
    for (std::size_t i = 0; i < curve.size(); ++i) {
        const Point2& at = curve[i];
        const Point2& next = curve[(i + 1) % curve.size()];
        const Point2 to_prev{prev.X - at.X, prev.Y - at.Y}, to_next{next.X - at.X, next.Y - at.Y};
        if (rightAngle(to_prev, to_next, p.min_side_um)) {
            const coord_um cut = std::min({side, lengthOf(to_prev) / 3, lengthOf(to_next) / 3});
            const Point2 a = scaledTo(to_prev, cut), b = scaledTo(to_next, cut);
            out.push_back({at.X + a.X, at.Y + a.Y});
            out.push_back({at.X + b.X, at.Y + b.Y});
        } else {
            out.push_back(at);
        }
        prev = at;
    }
    return out;
}

bool rootOnly(const SierpinskiTree& tree, const std::vector<int>& sequence) {
    return sequence.empty() || tree.node(sequence.front()).depth == 0;
}

}  // namespace

Path crossCurve(const SierpinskiTree& tree, const std::vector<int>& sequence) {
    Path curve;
    if (rootOnly(tree, sequence))
        return curve;
    curve.reserve(sequence.size());
    for (const int index : sequence)
        curve.push_back(exitMiddle(tree.node(index)));
    return curve;
}

Path cross3dCurve(const SierpinskiTree& tree, const std::vector<int>& sequence, const Cross3dParams& params) {
    Path curve;
    if (rootOnly(tree, sequence))
        return curve;
    curve.reserve(sequence.size() + 1);
    for (const int index : sequence) {
        const SierpinskiNode& n = tree.node(index);
        curve.push_back(crossingAt(entryEdge(n), shortSide(n), params));
    }
    const SierpinskiNode& last = tree.node(sequence.back());
    curve.push_back(crossingAt(exitEdge(last), shortSide(last), params));
    return params.pocket_um > 10 ? withPockets(curve, params) : curve;
}

}  // namespace mixengine
