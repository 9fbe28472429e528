#include "toolpaths/infill/cross/SierpinskiTree.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace mixengine {
namespace {

double lengthMm(const Point2& from, const Point2& to) {
    return distanceUm(from, to) / kMicronsPerMm;
}

/// The directions of the two children of a triangle crossed in direction `d`.
std::pair<CrossDirection, CrossDirection> childDirections(CrossDirection d) {
    switch (d) {
        case CrossDirection::AcToAb:
            return {CrossDirection::AbToBc, CrossDirection::AcToBc};
        case CrossDirection::AcToBc:
            return {CrossDirection::AbToBc, CrossDirection::AcToAb};
        default:
            return {CrossDirection::AcToBc, CrossDirection::AcToAb};
    }
}

SierpinskiNode makeNode(const Point2& c, const Point2& a, const Point2& b, CrossDirection d, bool c_is_left,
                        int depth) {
    SierpinskiNode n;
    n.c = c;
    n.a = a;
    n.b = b;
    n.direction = d;
    n.c_is_left = c_is_left;
    n.depth = depth;
    const double ac_mm = lengthMm(a, c);
    n.area_mm2 = static_cast<float>(0.5 * ac_mm * ac_mm);
    n.realized_mm = static_cast<float>(d == CrossDirection::AcToBc ? 0.5 * lengthMm(a, b) : 0.5 * ac_mm);
    return n;
}

CrossEdge oriented(CrossEdge e, bool c_is_left) {
    if (!c_is_left)
        std::swap(e.left, e.right);
    return e;
}

}  // namespace

CrossEdge entryEdge(const SierpinskiNode& n) {
    return oriented(n.direction == CrossDirection::AbToBc ? CrossEdge{n.a, n.b} : CrossEdge{n.c, n.a},
                    n.c_is_left);
}

CrossEdge exitEdge(const SierpinskiNode& n) {
    return oriented(n.direction == CrossDirection::AcToAb ? CrossEdge{n.b, n.a} : CrossEdge{n.c, n.b},
                    n.c_is_left);
}

SierpinskiTree::SierpinskiTree(const Box2& square, int max_depth, coord_um line_width_um,
                               const DensityAt& density)
    : max_depth_(std::max(max_depth, 0)) {
    nodes_.reserve(std::size_t{2} << std::min(max_depth_, 30));
    nodes_.emplace_back();  // the root: no corners, nothing realized
    const Point2 min{square.left, square.top}, max{square.right, square.bottom};
    const Point2 left_top{min.X, max.Y}, right_bottom{max.X, min.Y};
    if (max_depth_ > 0) {
        nodes_[0].first_child = 1;
        nodes_.push_back(makeNode(right_bottom, min, max, CrossDirection::AcToAb, false, 1));
        nodes_.push_back(makeNode(left_top, max, min, CrossDirection::AcToAb, false, 1));
        split(1);
        split(2);
    }
    fillRequested(kRoot, line_width_um, density);
}

void SierpinskiTree::split(int index) {
    const SierpinskiNode parent = node(index);
    if (parent.depth >= max_depth_)
        return;
    const Point2 middle{(parent.a.X + parent.b.X) / 2, (parent.a.Y + parent.b.Y) / 2};
    const auto [first, second] = childDirections(parent.direction);
    const int child = static_cast<int>(nodes_.size());
    node(index).first_child = child;
    nodes_.push_back(makeNode(middle, parent.a, parent.c, first, !parent.c_is_left, parent.depth + 1));
    nodes_.push_back(makeNode(middle, parent.c, parent.b, second, !parent.c_is_left, parent.depth + 1));
    split(child);
    split(child + 1);
}

void SierpinskiTree::fillRequested(int index, coord_um line_width_um, const DensityAt& density) {
    SierpinskiNode& n = node(index);  // the nodes are all made: references stay valid
    if (n.leaf()) {
        const Box2 box{std::min({n.a.X, n.b.X, n.c.X}), std::min({n.a.Y, n.b.Y, n.c.Y}),
                       std::max({n.a.X, n.b.X, n.c.X}), std::max({n.a.Y, n.b.Y, n.c.Y})};
        n.requested_mm = static_cast<float>(double(density(box) * n.area_mm2) / micronsToMm(line_width_um));
        return;
    }
    const int first = n.first_child;
    for (const int child : {first, first + 1}) {
        fillRequested(child, line_width_um, density);
        n.requested_mm += node(child).requested_mm;
        n.child_realized_mm += node(child).realized_mm;
    }
}

}  // namespace mixengine
