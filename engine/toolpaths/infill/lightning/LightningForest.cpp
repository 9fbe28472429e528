#include "toolpaths/infill/lightning/LightningForest.h"

#include <algorithm>

#include "geometry/PointQueries.h"

namespace mixengine {

int LightningForest::addRoot(Point2 p, std::optional<Point2> last_ground) {
    nodes.push_back({p, kNoNode, {}, last_ground});
    roots.push_back(static_cast<int>(nodes.size()) - 1);
    return roots.back();
}

int LightningForest::addChild(int parent, Point2 p) {
    nodes.push_back({p, parent, {}, std::nullopt});
    const int child = static_cast<int>(nodes.size()) - 1;
    nodes[static_cast<std::size_t>(parent)].children.push_back(child);
    return child;
}

void LightningForest::attach(int parent, int child) {
    nodes[static_cast<std::size_t>(parent)].children.push_back(child);
    nodes[static_cast<std::size_t>(child)].parent = parent;
}

void LightningForest::detach(int child) {
    LightningNode& node = nodes[static_cast<std::size_t>(child)];
    if (node.parent == kNoNode)
        return;
    std::vector<int>& siblings = nodes[static_cast<std::size_t>(node.parent)].children;
    siblings.erase(std::remove(siblings.begin(), siblings.end(), child), siblings.end());
    node.parent = kNoNode;
}

void LightningForest::reroot(int node) {
    // Reverse the links from the old root down to `node`, top first.
    std::vector<int> path;
    for (int n = node; n != kNoNode; n = nodes[static_cast<std::size_t>(n)].parent)
        path.push_back(n);
    for (std::size_t i = path.size(); i-- > 1;) {
        const int upper = path[i], lower = path[i - 1];
        std::vector<int>& children = nodes[static_cast<std::size_t>(upper)].children;
        children.erase(std::remove(children.begin(), children.end(), lower), children.end());
        nodes[static_cast<std::size_t>(lower)].children.push_back(upper);
        nodes[static_cast<std::size_t>(upper)].parent = lower;
    }
    nodes[static_cast<std::size_t>(node)].parent = kNoNode;
}

int LightningForest::closestNode(int root, Point2 p) const {
    int best = root;
    double best2 = distance2(nodes[static_cast<std::size_t>(root)].p, p);
    std::vector<int> stack{root};
    while (!stack.empty()) {
        const int n = stack.back();
        stack.pop_back();
        const double d2 = distance2(nodes[static_cast<std::size_t>(n)].p, p);
        if (d2 < best2)
            best2 = d2, best = n;
        const std::vector<int>& children = nodes[static_cast<std::size_t>(n)].children;
        stack.insert(stack.end(), children.rbegin(), children.rend());
    }
    return best;
}

bool LightningForest::holds(int top, int node) const {
    for (int n = node; n != kNoNode; n = nodes[static_cast<std::size_t>(n)].parent) {
        if (n == top)
            return true;
    }
    return false;
}

int LightningForest::valence(int node) const {
    const LightningNode& n = nodes[static_cast<std::size_t>(node)];
    return static_cast<int>(n.children.size()) + (n.parent != kNoNode ? 1 : 0);
}

int LightningForest::copyTree(const LightningForest& from, int root) {
    const LightningNode& source = from.nodes[static_cast<std::size_t>(root)];
    nodes.push_back({source.p, kNoNode, {}, source.last_ground.value_or(source.p)});
    const int top = static_cast<int>(nodes.size()) - 1;
    // (original, copy) pairs still to visit
    std::vector<std::pair<int, int>> stack{{root, top}};
    while (!stack.empty()) {
        const auto [original, copy] = stack.back();
        stack.pop_back();
        for (int child : from.nodes[static_cast<std::size_t>(original)].children) {
            const int made = addChild(copy, from.nodes[static_cast<std::size_t>(child)].p);
            stack.push_back({child, made});
        }
    }
    return top;
}

}  // namespace mixengine
