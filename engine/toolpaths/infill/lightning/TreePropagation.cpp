#include "toolpaths/infill/lightning/TreePropagation.h"

#include <algorithm>
#include <cmath>

#include "geometry/PointQueries.h"

namespace mixengine {
namespace {

LightningNode& at(LightningForest& forest, int n) {
    return forest.nodes[static_cast<std::size_t>(n)];
}

/// v scaled to `length` (CuraEngine's normal(): a zero vector gives (length, 0)).
Point2 scaledTo(Point2 v, double length) {
    const double size = std::sqrt(distance2(v, {0, 0}));
    if (size < 1)
        return {static_cast<coord_um>(length), 0};
    return {std::llround(double(v.X) * length / size), std::llround(double(v.Y) * length / size)};
}

Point2 plus(Point2 a, Point2 b) {
    return {a.X + b.X, a.Y + b.Y};
}

Point2 minus(Point2 a, Point2 b) {
    return {a.X - b.X, a.Y - b.Y};
}

/// The square of the distance from p to segment a–b.
double distance2ToSegment(Point2 a, Point2 b, Point2 p) {
    const double dx = double(b.X - a.X), dy = double(b.Y - a.Y);
    const double length2 = dx * dx + dy * dy;
    const double t = length2 <= 0
                         ? 0.0
                         : std::clamp((double(p.X - a.X) * dx + double(p.Y - a.Y) * dy) / length2, 0.0, 1.0);
    const double ex = double(a.X) + t * dx - double(p.X), ey = double(a.Y) + t * dy - double(p.Y);
    return ex * ex + ey * ey;
}

double pruneBelow(LightningForest& forest, int n, double prune) {
    double most = 0;
    std::vector<int>& children = at(forest, n).children;
    for (std::size_t i = 0; i < children.size();) {
        const int child = children[i];
        const double pruned = pruneBelow(forest, child, prune);
        if (pruned >= prune) {
            most = std::max(most, pruned);
            ++i;
            continue;
        }
        const Point2 a = at(forest, n).p, b = at(forest, child).p;
        const double length = distanceUm(a, b);
        if (pruned + length <= prune) {  // the whole branch goes
            most = std::max(most, pruned + length);
            at(forest, child).parent = kNoNode;
            children.erase(children.begin() + static_cast<std::ptrdiff_t>(i));
        } else {  // the branch now ends between the two
            at(forest, child).p = plus(b, scaledTo(minus(a, b), prune - pruned));
            most = prune;
            ++i;
        }
    }
    return most;
}

struct Junction {
    double run_um = 0;  ///< length along the tree from the junction above to this one
    Point2 p{0, 0};
};

struct Straightening {
    double magnitude = 0;
    double colinear2 = 0;
};

Junction straightenBelow(LightningForest& forest, int n, const Straightening& s, Point2 above, double run);

/// Drops node n (one child) when it lies on the line from its parent to its child.
void dropWhenColinear(LightningForest& forest, int n, const Straightening& s) {
    const LightningNode& node = at(forest, n);
    const int child = node.children.front();
    if (node.parent == kNoNode)
        return;
    const Point2 up = at(forest, node.parent).p, down = at(forest, child).p;
    if (distance2(up, down) >= s.colinear2 || distance2ToSegment(up, down, node.p) >= 10)
        return;
    at(forest, child).parent = node.parent;
    for (int& sibling : at(forest, node.parent).children) {
        if (sibling == n) {
            sibling = child;
            break;
        }
    }
}

/// A node on a run: towards the line between the junctions above and below.
Junction straightenRun(LightningForest& forest, int n, const Straightening& s, Point2 above, double run) {
    const int child = at(forest, n).children.front();
    const double to_child = distanceUm(at(forest, n).p, at(forest, child).p);
    const Junction below = straightenBelow(forest, child, s, above, run + to_child);
    if (above.X != below.p.X || above.Y != below.p.Y) {
        const double k = run / std::max(1.0, below.run_um);
        const Point2 target{above.X + std::llround(double(below.p.X - above.X) * k),
                            above.Y + std::llround(double(below.p.Y - above.Y) * k)};
        Point2& p = at(forest, n).p;
        const Point2 step = minus(target, p);
        const bool near = std::abs(double(step.X)) <= s.magnitude &&
                          std::abs(double(step.Y)) <= s.magnitude &&
                          distance2(step, {0, 0}) < s.magnitude * s.magnitude;
        p = near ? target : plus(p, scaledTo(step, s.magnitude));
    }
    dropWhenColinear(forest, n, s);
    return below;
}

/// A junction (or an end): towards the mean direction of its branches.
Junction straightenJunction(LightningForest& forest, int n, const Straightening& s, Point2 above,
                            double run) {
    constexpr double kWeight = 1000;
    const Point2 p = at(forest, n).p;
    Point2 direction = scaledTo(minus(above, p), kWeight);
    bool keep = false;  // a short branch: moving the junction would fight its straightening
    for (std::size_t i = 0; i < at(forest, n).children.size(); ++i) {
        const int child = at(forest, n).children[i];
        const Junction below = straightenBelow(forest, child, s, p, distanceUm(p, at(forest, child).p));
        direction = plus(direction, scaledTo(minus(below.p, p), kWeight));
        keep = keep || below.run_um < s.magnitude;
    }
    const LightningNode& node = at(forest, n);
    if ((direction.X != 0 || direction.Y != 0) && !node.children.empty() && node.parent != kNoNode && !keep) {
        const double limit = s.magnitude * 3 / 4;
        const double length = std::sqrt(distance2(direction, {0, 0}));
        if (length > limit)
            direction = scaledTo(direction, limit);
        at(forest, n).p = plus(p, direction);
    }
    return {run, at(forest, n).p};
}

Junction straightenBelow(LightningForest& forest, int n, const Straightening& s, Point2 above, double run) {
    if (at(forest, n).children.size() == 1)
        return straightenRun(forest, n, s, above, run);
    return straightenJunction(forest, n, s, above, run);
}

/// Whether node n stays (it lies inside the outline); the pieces cut off go to forest.roots.
bool realign(LightningForest& forest, int n, const Paths& outlines, const OutlineGrid& grid,
             coord_um reach_um) {
    if (grid.empty())
        return false;
    const Point2 p = at(forest, n).p;
    const std::vector<int> children = at(forest, n).children;
    std::vector<int> kept;
    if (!insideArea(outlines, p, true)) {  // lift the branches that come back inside out of the tree
        for (int child : children) {
            if (realign(forest, child, outlines, grid, reach_um)) {
                at(forest, child).last_ground = p;
                at(forest, child).parent = kNoNode;
                forest.roots.push_back(child);
            }
        }
        at(forest, n).children.clear();
        return false;
    }
    bool reground = false;
    for (int child : children) {
        if (!realign(forest, child, outlines, grid, reach_um))
            continue;
        if (grid.crossingNearEnd(at(forest, child).p, p, reach_um)) {
            at(forest, child).last_ground.reset();
            at(forest, child).parent = kNoNode;
            forest.roots.push_back(child);
            reground = true;
            continue;
        }
        kept.push_back(child);
    }
    at(forest, n).children = std::move(kept);
    if (reground)
        at(forest, n).last_ground.reset();
    return true;
}

}  // namespace

coord_um pruneTree(LightningForest& forest, int root, coord_um prune_um) {
    if (prune_um <= 0)
        return 0;
    return static_cast<coord_um>(pruneBelow(forest, root, double(prune_um)));
}

void straightenTree(LightningForest& forest, int root, coord_um straighten_um, coord_um colinear_um) {
    const Straightening s{double(straighten_um), double(colinear_um) * double(colinear_um)};
    straightenBelow(forest, root, s, at(forest, root).p, 0);
}

void propagateTree(const LightningForest& above, int root, const Paths& outlines, const OutlineGrid& grid,
                   const PropagationParams& params, LightningForest& below) {
    const int top = below.copyTree(above, root);
    pruneTree(below, top, params.prune_um);
    straightenTree(below, top, params.straighten_um, params.colinear_um);
    if (realign(below, top, outlines, grid, params.crossing_reach_um))
        below.roots.push_back(top);
}

}  // namespace mixengine
