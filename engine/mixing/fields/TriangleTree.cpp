#include "mixing/fields/TriangleTree.h"

#include <algorithm>
#include <limits>

#include "mixing/fields/PaintedRegions.h"

namespace mixengine {

double squaredDistanceToBox(const double p[3], const double lo[3], const double hi[3]) {
    double sum = 0;
    for (int k = 0; k < 3; ++k) {
        const double d = p[k] < lo[k] ? lo[k] - p[k] : (p[k] > hi[k] ? p[k] - hi[k] : 0.0);
        sum += d * d;
    }
    return sum;
}

namespace {

constexpr std::uint32_t kLeafSize = 4;
/// Median splits halve the triangles per level: 2^64 triangles would not fill the search's stack.
constexpr std::size_t kMaxDepth = 128;

double centre(const TriangleTree::Corners& t, int axis) {
    return (t[static_cast<std::size_t>(axis)] + t[static_cast<std::size_t>(3 + axis)] +
            t[static_cast<std::size_t>(6 + axis)]) /
           3;
}

}  // namespace

TriangleTree::TriangleTree(std::vector<Corners> triangles) : triangles_(std::move(triangles)) {
    for (const Corners& t : triangles_) {
        std::array<double, 6> box{};
        for (int k = 0; k < 3; ++k) {
            box[static_cast<std::size_t>(k)] =
                std::min({t[static_cast<std::size_t>(k)], t[static_cast<std::size_t>(3 + k)],
                          t[static_cast<std::size_t>(6 + k)]});
            box[static_cast<std::size_t>(3 + k)] =
                std::max({t[static_cast<std::size_t>(k)], t[static_cast<std::size_t>(3 + k)],
                          t[static_cast<std::size_t>(6 + k)]});
        }
        boxes_.push_back(box);
    }
    order_.resize(triangles_.size());
    for (std::uint32_t i = 0; i < order_.size(); ++i)
        order_[i] = i;
    if (!triangles_.empty()) {
        nodes_.reserve(2 * triangles_.size() / kLeafSize + 2);
        build(0, static_cast<std::uint32_t>(order_.size()));
    }
}

std::uint32_t TriangleTree::build(std::uint32_t begin, std::uint32_t end) {
    const auto index = static_cast<std::uint32_t>(nodes_.size());
    Node node;
    std::fill(node.lo, node.lo + 3, std::numeric_limits<double>::max());
    std::fill(node.hi, node.hi + 3, std::numeric_limits<double>::lowest());
    for (std::uint32_t i = begin; i < end; ++i)
        for (int c = 0; c < 9; ++c) {
            const double v = triangles_[order_[i]][static_cast<std::size_t>(c)];
            node.lo[c % 3] = std::min(node.lo[c % 3], v);
            node.hi[c % 3] = std::max(node.hi[c % 3], v);
        }
    nodes_.push_back(node);
    if (end - begin <= kLeafSize) {
        nodes_[index].first = begin;
        nodes_[index].count = end - begin;
        return index;
    }
    int axis = 0;
    for (int k = 1; k < 3; ++k)
        if (node.hi[k] - node.lo[k] > node.hi[axis] - node.lo[axis])
            axis = k;
    const std::uint32_t middle = begin + (end - begin) / 2;
    std::nth_element(order_.begin() + begin, order_.begin() + middle, order_.begin() + end,
                     [&](std::uint32_t a, std::uint32_t b) {
                         return centre(triangles_[a], axis) < centre(triangles_[b], axis);
                     });
    build(begin, middle);
    const std::uint32_t right = build(middle, end);
    nodes_[index].first = right;
    return index;
}

std::pair<double, int> TriangleTree::nearest(const double p[3], double limit_sq) const {
    std::pair<double, int> best{limit_sq, -1};
    std::array<std::uint32_t, kMaxDepth> stack{};
    std::size_t size = nodes_.empty() ? 0 : 1;  // the root, node 0
    while (size > 0) {
        const std::uint32_t at = stack[--size];
        const Node& node = nodes_[at];
        if (squaredDistanceToBox(p, node.lo, node.hi) >= best.first)
            continue;
        if (node.count > 0) {
            for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
                const std::array<double, 6>& box = boxes_[order_[i]];
                if (squaredDistanceToBox(p, &box[0], &box[3]) >= best.first)
                    continue;  // its own box is no nearer
                const Corners& t = triangles_[order_[i]];
                const double d = squaredDistanceToTriangle(p, &t[0], &t[3], &t[6]);
                if (d < best.first)
                    best = {d, static_cast<int>(order_[i])};
            }
            continue;
        }
        const std::uint32_t left = at + 1, right = node.first;
        const bool left_first = squaredDistanceToBox(p, nodes_[left].lo, nodes_[left].hi) <=
                                squaredDistanceToBox(p, nodes_[right].lo, nodes_[right].hi);
        stack[size++] = left_first ? right : left;  // the nearer child is searched first
        stack[size++] = left_first ? left : right;
    }
    return best;
}

}  // namespace mixengine
