#include "toolpaths/infill/lightning/TreeGrowth.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "geometry/PointQueries.h"

namespace mixengine {
namespace {

long long floorDiv(coord_um a, coord_um b) {
    return a >= 0 ? a / b : -((-a + b - 1) / b);
}

/// The trees' nodes in square cells, in the order they were added.
class NodeGrid {
  public:
    explicit NodeGrid(coord_um cell_um) : cell_um_(std::max<coord_um>(cell_um, 1)) {}

    void insert(int node, Point2 p) {
        cells_[key(floorDiv(p.X, cell_um_), floorDiv(p.Y, cell_um_))].push_back(node);
    }

    /// Every node of the forest's trees, each tree depth first.
    void insertAll(const LightningForest& forest) {
        for (int root : forest.roots) {
            std::vector<int> stack{root};
            while (!stack.empty()) {
                const int n = stack.back();
                stack.pop_back();
                const LightningNode& node = forest.nodes[static_cast<std::size_t>(n)];
                insert(n, node.p);
                stack.insert(stack.end(), node.children.rbegin(), node.children.rend());
            }
        }
    }

    /// The nodes in the cells that the square of half side `radius_um` around p reaches, cells row by
    /// row (as CuraEngine's node grid: nodes up to a cell beyond the radius count too).
    std::vector<int> near(Point2 p, coord_um radius_um) const {
        std::vector<int> found;
        for (long long y = floorDiv(p.Y - radius_um, cell_um_); y <= floorDiv(p.Y + radius_um, cell_um_);
             ++y) {
            for (long long x = floorDiv(p.X - radius_um, cell_um_); x <= floorDiv(p.X + radius_um, cell_um_);
                 ++x) {
                const auto cell = cells_.find(key(x, y));
                if (cell != cells_.end())
                    found.insert(found.end(), cell->second.begin(), cell->second.end());
            }
        }
        return found;
    }

  private:
    static std::int64_t key(long long x, long long y) { return (x << 32) ^ (y & 0xffffffffLL); }

    coord_um cell_um_;
    std::unordered_map<std::int64_t, std::vector<int>> cells_;
};

struct Ground {
    int node = kNoNode;  ///< the tree node to hang from, or none: the outline point
    Point2 outline{0, 0};
};

double weightedDistance(const LightningForest& forest, int node, Point2 p, coord_um radius_um) {
    const int links = forest.valence(node);
    const double boost = links > 0 && links < 4 ? 4.0 * double(radius_um) : 0.0;
    return std::floor(std::sqrt(distance2(forest.nodes[static_cast<std::size_t>(node)].p, p))) - boost;
}

/// The best place to hold p from: a tree node (not of the tree under `exclude`) or the outline.
Ground bestGround(const LightningForest& forest, Point2 p, const OutlineGrid& outline, const NodeGrid& nodes,
                  coord_um radius_um, coord_um trees_from_um, int exclude) {
    Ground ground{kNoNode, *outline.nearest(p)};
    const double to_outline = std::floor(std::sqrt(distance2(ground.outline, p)));
    if (to_outline < double(trees_from_um))
        return ground;
    double best = to_outline;
    for (int n : nodes.near(p, static_cast<coord_um>(to_outline))) {
        if (exclude != kNoNode && forest.holds(exclude, n))
            continue;
        if (outline.touches(p, forest.nodes[static_cast<std::size_t>(n)].p))
            continue;
        const double weighted = weightedDistance(forest, n, p, radius_um);
        if (weighted < best)
            best = weighted, ground.node = n;
    }
    return ground;
}

/// A new root at p, not listed in forest.roots.
int newFreeRoot(LightningForest& forest, Point2 p) {
    forest.nodes.push_back({p, kNoNode, {}, p});
    return static_cast<int>(forest.nodes.size()) - 1;
}

/// Extends the tree under `root` from its root towards where it last hung, up to the outline;
/// the new root, or none when the outline is not crossed near that place.
int extendToOutline(LightningForest& forest, int root, const OutlineGrid& outline,
                    const GrowthParams& params) {
    const LightningNode& node = forest.nodes[static_cast<std::size_t>(root)];
    if (!node.last_ground || (node.last_ground->X == node.p.X && node.last_ground->Y == node.p.Y))
        return kNoNode;
    const std::optional<Point2> crossing =
        outline.crossingNearEnd(node.p, *node.last_ground, params.crossing_reach_um);
    if (!crossing)
        return kNoNode;
    const int top = newFreeRoot(forest, *crossing);
    forest.attach(top, root);
    return top;
}

}  // namespace

void growNewBranches(LightningForest& forest, UnsupportedPoints& unsupported, const OutlineGrid& outline,
                     const GrowthParams& params) {
    if (outline.empty())
        return;
    NodeGrid nodes(params.node_cell_um);
    nodes.insertAll(forest);
    Point2 p;
    while (unsupported.next(p)) {
        const Ground ground =
            bestGround(forest, p, outline, nodes, params.radius_um, params.wall_reach_um, kNoNode);
        int parent = ground.node;
        if (parent == kNoNode) {
            parent = forest.addRoot(ground.outline, ground.outline);
            nodes.insert(parent, ground.outline);
        }
        nodes.insert(forest.addChild(parent, p), p);
        unsupported.holdAround(p);
    }
}

void reconnectCarried(LightningForest& forest, const std::vector<int>& carried, const OutlineGrid& outline,
                      const GrowthParams& params) {
    if (outline.empty())
        return;
    NodeGrid nodes(params.node_cell_um);
    nodes.insertAll(forest);
    constexpr coord_um kTreeGroundMargin = 100;
    for (int root : carried) {
        const auto slot = std::find(forest.roots.begin(), forest.roots.end(), root);
        if (slot == forest.roots.end())
            continue;
        const std::size_t at = static_cast<std::size_t>(slot - forest.roots.begin());
        const int extended = extendToOutline(forest, root, outline, params);
        if (extended != kNoNode) {
            nodes.insert(extended, forest.nodes[static_cast<std::size_t>(extended)].p);
            forest.roots[at] = extended;
            continue;
        }
        const Point2 p = forest.nodes[static_cast<std::size_t>(root)].p;
        const Ground ground = bestGround(forest, p, outline, nodes, params.radius_um,
                                         params.wall_reach_um - kTreeGroundMargin, root);
        if (ground.node == kNoNode) {
            if (distance2(ground.outline, p) <= 2)  // on the outline already
                continue;
            const int top = newFreeRoot(forest, ground.outline);
            const int hold = forest.closestNode(root, ground.outline);
            forest.reroot(hold);
            forest.attach(top, hold);
            nodes.insert(top, ground.outline);
            forest.roots[at] = top;
        } else {
            const int hold = forest.closestNode(root, forest.nodes[static_cast<std::size_t>(ground.node)].p);
            forest.reroot(hold);
            forest.attach(ground.node, hold);
            forest.roots[at] = forest.roots.back();
            forest.roots.pop_back();
        }
    }
}

}  // namespace mixengine
