#pragma once
// The lightning trees of one layer (toolpaths/infill/lightning/LightningInfill.h), as nodes in one
// array linked by index. A tree's root lies on the layer's infill outline; its branches reach in
// to the points the layer above needs held up. Nodes cut out of a tree stay in the array,
// unreachable; copyTree takes only what a tree still reaches.
//
// Contract: `roots` lists the trees in the order they were made; a node is a root exactly when
// its parent is kNoNode; children are kept in the order they were attached.
#include <optional>
#include <vector>

#include "geometry/Point.h"

namespace mixengine {

constexpr int kNoNode = -1;

struct LightningNode {
    Point2 p{0, 0};
    int parent = kNoNode;
    std::vector<int> children;
    /// For a root: where it was last held (on the outline), or where the part it hung from was
    /// before the layer below cut that part away; nothing once a crossing of the outline cut it off.
    std::optional<Point2> last_ground;
};

struct LightningForest {
    std::vector<LightningNode> nodes;
    std::vector<int> roots;

    /// A new tree of one node (added to `roots`).
    int addRoot(Point2 p, std::optional<Point2> last_ground);
    /// A new leaf under `parent`.
    int addChild(int parent, Point2 p);
    /// Hangs the root `child` (of another tree; not in `roots` any more) under `parent`.
    void attach(int parent, int child);
    /// Cuts `child` from its parent: it becomes a root (not added to `roots`).
    void detach(int child);
    /// Turns the tree so that `node` is its root (the links on the way up are reversed).
    void reroot(int node);
    /// The node of the tree under `root` nearest to p (the first of equals, depth first).
    int closestNode(int root, Point2 p) const;
    /// Whether `node` lies in the tree under `top` (top itself included).
    bool holds(int top, int node) const;
    /// Links of the node: its children and one for its parent.
    int valence(int node) const;
    /// Copies the tree under `root` of `from` into this forest as a new tree (not added to `roots`);
    /// a copied root keeps its last_ground, or takes its own place when it has none.
    int copyTree(const LightningForest& from, int root);
};

}  // namespace mixengine
