#include "toolpaths/support/TreeNodes.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/Clip.h"
#include "geometry/PointQueries.h"
#include "geometry/PolygonOps.h"

namespace mixengine {
namespace {

constexpr double kGridTurnRadians = 22.0 / 180.0 * 3.14159265358979323846;  // as CuraEngine
constexpr coord_um kRoundingMarginUm = 100;

bool inBounds(const Box2& b, Point2 p) {
    return p.X >= b.left && p.X <= b.right && p.Y >= b.top && p.Y <= b.bottom;
}

Box2 grown(Box2 b, coord_um by) {
    return {b.left - by, b.top - by, b.right + by, b.bottom + by};
}

Point2 middleOf(const Box2& b) {
    return {(b.left + b.right) / 2, (b.top + b.bottom) / 2};
}

/// The grid, turned about the bounds' middle, that falls in the bounds.
std::vector<Point2> contactGrid(const Box2& bounds, coord_um spacing_um) {
    const double c = std::cos(kGridTurnRadians), s = std::sin(kGridTurnRadians);
    const double w = double(bounds.right - bounds.left), h = double(bounds.bottom - bounds.top);
    const coord_um half_x = std::llround((w * c + h * s) / 2), half_y = std::llround((w * s + h * c) / 2);
    const Point2 middle = middleOf(bounds);
    const coord_um step = std::max<coord_um>(1, spacing_um);
    std::vector<Point2> grid;
    for (coord_um x = -half_x; x <= half_x; x += step) {
        for (coord_um y = -half_y; y <= half_y; y += step) {
            const Point2 p{middle.X + std::llround(double(x) * c - double(y) * s),
                           middle.Y + std::llround(double(x) * s + double(y) * c)};
            if (inBounds(bounds, p))
                grid.push_back(p);
        }
    }
    return grid;
}

TreeNode contactNode(Point2 at, int layer_of_overhang, int roof_layers) {
    TreeNode node;
    node.position = at;
    node.skin_direction = layer_of_overhang % 2 == 1;
    node.roof_layers_below = roof_layers;
    return node;
}

/// The contact points of one overhang loop on `layer` (see the header).
void addLoopContacts(const Path& loop, const std::vector<Point2>& grid, const Box2& mesh_bounds,
                     const TreeContactParams& p, const Paths& collision, int layer,
                     std::vector<TreeNode>& out) {
    const Box2 near = grown(boundsOf(Paths{loop}), p.half_overhang_step_um);
    const double reach2 = double(p.half_overhang_step_um) * double(p.half_overhang_step_um);
    bool added = false;
    for (Point2 candidate : grid) {
        if (!inBounds(near, candidate))
            continue;
        moveOntoLoop(loop, candidate, reach2);
        if (insideLoop(loop, candidate) && !insideArea(collision, candidate, true)) {
            out.push_back(contactNode(candidate, layer + p.z_layers, p.roof_layers));
            added = true;
        }
    }
    if (!added) {  // a loop between the grid points still gets one
        Point2 candidate = middleOf(mesh_bounds);
        moveOntoLoop(loop, candidate, -1);
        out.push_back(contactNode(candidate, layer, p.roof_layers));
    }
}

void dropContactsInHoles(const Paths& overhang, std::vector<TreeNode>& nodes) {
    for (const Path& loop : overhang) {
        if (counterClockwise(loop))
            continue;
        std::erase_if(nodes, [&](const TreeNode& n) {
            return !n.removed && n.sources.empty() && n.distance_to_top == 0 &&
                   pointInLoop(n.position, loop) == 1;
        });
    }
}

}  // namespace

void addContactPoints(const std::vector<Paths>& overhang, const Box2& bounds, const TreeContactParams& params,
                      TreeVolumes& volumes, TreeLayers& layers) {
    const std::vector<Point2> grid = contactGrid(bounds, params.branch_distance_um);
    const int count = static_cast<int>(std::min(overhang.size(), layers.size()));
    for (int layer = 1; layer < count - params.z_layers; ++layer) {
        const Paths& above = overhang[static_cast<std::size_t>(layer + params.z_layers)];
        if (above.empty())
            continue;
        std::vector<TreeNode>& nodes = layers[static_cast<std::size_t>(layer)];
        const Paths& collision = volumes.collision(0, layer);
        for (const Path& loop : above)
            addLoopContacts(loop, grid, bounds, params, collision, layer, nodes);
        dropContactsInHoles(above, nodes);
    }
}

coord_um droppingRadius(const TreeDropParams& p, coord_um layer_height_um, int distance_to_top) {
    const int tip_layers = static_cast<int>(p.branch_radius_um / std::max<coord_um>(1, layer_height_um));
    const double r = double(p.branch_radius_um);
    if (distance_to_top > tip_layers || tip_layers == 0)
        return std::llround(r + r * distance_to_top * p.radius_growth_per_layer);
    return std::llround(r * distance_to_top / tip_layers);
}

namespace {

/// One layer's dropping (see the header): `layer` > 0, its nodes go to layer − 1.
class LayerDrop {
  public:
    LayerDrop(const TreeDropParams& p, coord_um layer_height, TreeVolumes& volumes, TreeLayers& layers,
              int layer)
        : p_(p),
          height_(layer_height),
          volumes_(volumes),
          layers_(layers),
          layer_(layer),
          nodes_(layers[static_cast<std::size_t>(layer)]) {}

    void run() {
        const std::vector<std::vector<std::size_t>> all = groups();
        for (std::size_t g = 0; g < all.size(); ++g) {
            plate_group_ = g == 0;
            dropGroup(all[g]);
        }
    }

    /// Removes node `index` of `layer` and every node above that went into it.
    static void prune(TreeLayers& layers, int layer, std::size_t index) {
        std::vector<std::pair<int, std::size_t>> todo{{layer, index}};
        while (!todo.empty()) {
            const auto [l, i] = todo.back();
            todo.pop_back();
            TreeNode& node = layers[static_cast<std::size_t>(l)][i];
            if (node.removed)
                continue;
            node.removed = true;
            for (std::size_t source : node.sources)
                todo.push_back({l + 1, source});
        }
    }

  private:
    std::vector<std::vector<std::size_t>> groups() {
        const std::vector<Paths> parts = splitIslands(volumes_.avoidance(0, layer_));
        std::vector<std::vector<std::size_t>> out(parts.size() + 1);
        for (std::size_t i = 0; i < nodes_.size(); ++i) {
            const TreeNode& node = nodes_[i];
            if (node.removed)
                continue;
            if (!p_.rests_on_model && !node.to_buildplate) {
                prune(layers_, layer_, i);
                continue;
            }
            out[node.to_buildplate || parts.empty() ? 0 : 1 + nearestPart(parts, node.position)].push_back(i);
        }
        return out;
    }

    static std::size_t nearestPart(const std::vector<Paths>& parts, Point2 p) {
        std::size_t best = 0;
        double best_d2 = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < parts.size(); ++i) {
            if (insideArea(parts[i], p, true))
                return i;
            const double d2 = nearestOnOutline(parts[i], p).distance2_um2;
            if (d2 >= 0 && d2 < best_d2) {
                best_d2 = d2;
                best = i;
            }
        }
        return best;
    }

    coord_um radius(int distance_to_top) const { return droppingRadius(p_, height_, distance_to_top); }
    double maxMove2() const { return double(p_.max_move_um) * double(p_.max_move_um); }

    /// Keeps a node that can reach the plate out of the avoidance below; whether it still can.
    bool placeBelow(bool towards_plate, coord_um r, Point2& at) {
        const Paths& avoid = volumes_.avoidance(r, layer_ - 1);
        if (towards_plate) {
            const double reach = double(p_.max_move_um + p_.resolution_um + kRoundingMarginUm);
            moveOutOf(avoid, at, p_.resolution_um + kRoundingMarginUm, reach * reach);
        }
        return !insideArea(avoid, at, true);
    }

    void insertBelow(TreeNode node) {
        std::vector<TreeNode>& below = layers_[static_cast<std::size_t>(layer_ - 1)];
        for (TreeNode& other : below) {
            if (other.removed || other.position != node.position)
                continue;
            other.distance_to_top = std::max(other.distance_to_top, node.distance_to_top);
            other.roof_layers_below = std::max(other.roof_layers_below, node.roof_layers_below);
            other.sources.insert(other.sources.end(), node.sources.begin(), node.sources.end());
            return;
        }
        below.push_back(std::move(node));
    }

    void dropGroup(const std::vector<std::size_t>& group) {
        if (group.empty())
            return;
        std::vector<Point2> points;
        for (std::size_t i : group)
            points.push_back(nodes_[i].position);
        const std::vector<std::vector<std::size_t>> tree = spanningTreeNeighbours(points);
        std::vector<bool> absorbed(group.size(), false);
        std::vector<std::vector<std::size_t>> swallowed(group.size());
        mergePass(group, points, tree, absorbed, swallowed);
        movePass(group, points, tree, absorbed, swallowed);
    }

    void mergePair(const std::vector<std::size_t>& group, const std::vector<Point2>& points, std::size_t a,
                   std::size_t b) {
        const TreeNode& na = nodes_[group[a]];
        const TreeNode& nb = nodes_[group[b]];
        TreeNode next;
        next.position = {(points[a].X + points[b].X) / 2, (points[a].Y + points[b].Y) / 2};
        next.distance_to_top = std::max(na.distance_to_top, nb.distance_to_top) + 1;
        next.roof_layers_below = std::max(na.roof_layers_below, nb.roof_layers_below) - 1;
        next.skin_direction = na.skin_direction;
        next.to_buildplate = placeBelow(plate_group_, radius(na.distance_to_top + 1), next.position);
        next.sources = {group[a], group[b]};
        insertBelow(std::move(next));
    }

    void mergePass(const std::vector<std::size_t>& group, const std::vector<Point2>& points,
                   const std::vector<std::vector<std::size_t>>& tree, std::vector<bool>& absorbed,
                   std::vector<std::vector<std::size_t>>& swallowed) {
        for (std::size_t a = 0; a < group.size(); ++a) {
            if (absorbed[a])
                continue;
            const std::vector<std::size_t>& near = tree[a];
            if (near.size() == 1 && distance2(points[a], points[near[0]]) < maxMove2() &&
                tree[near[0]].size() == 1) {
                mergePair(group, points, a, near[0]);
                absorbed[a] = absorbed[near[0]] = true;
                continue;
            }
            if (near.size() < 2)
                continue;
            TreeNode& node = nodes_[group[a]];
            for (std::size_t b : near) {
                if (distance2(points[a], points[b]) >= maxMove2())
                    continue;
                const TreeNode& other = nodes_[group[b]];
                node.distance_to_top = std::max(node.distance_to_top, other.distance_to_top);
                node.roof_layers_below = std::max(node.roof_layers_below, other.roof_layers_below);
                swallowed[a].push_back(group[b]);
                swallowed[a].insert(swallowed[a].end(), swallowed[b].begin(), swallowed[b].end());
                absorbed[b] = true;
            }
        }
    }

    /// Whether node `a` (of a group resting on the model) has ended: deeper in the model's
    /// collision area than its radius.
    bool endsOnModel(const TreeNode& node) {
        const Paths& collision = volumes_.collision(0, layer_);
        if (!insideArea(collision, node.position, true))
            return false;
        const double r = double(radius(node.distance_to_top));
        return nearestOnOutline(collision, node.position).distance2_um2 >= r * r;
    }

    Point2 stepTowardsNeighbours(Point2 at, const std::vector<Point2>& points,
                                 const std::vector<std::size_t>& near) {
        if (near.empty() || (near.size() == 1 && distance2(at, points[near[0]]) < maxMove2()))
            return at;
        double sx = 0, sy = 0;
        for (std::size_t b : near) {
            sx += double(points[b].X - at.X);
            sy += double(points[b].Y - at.Y);
        }
        const double length = std::hypot(sx, sy);
        const double scale = length <= double(p_.max_move_um) ? 1.0 : double(p_.max_move_um) / length;
        return {at.X + std::llround(sx * scale), at.Y + std::llround(sy * scale)};
    }

    void movePass(const std::vector<std::size_t>& group, const std::vector<Point2>& points,
                  const std::vector<std::vector<std::size_t>>& tree, const std::vector<bool>& absorbed,
                  const std::vector<std::vector<std::size_t>>& swallowed) {
        for (std::size_t a = 0; a < group.size(); ++a) {
            if (absorbed[a] || nodes_[group[a]].removed)
                continue;
            const TreeNode& node = nodes_[group[a]];
            if (!plate_group_ && endsOnModel(node)) {
                if (!p_.rests_on_model)
                    prune(layers_, layer_, group[a]);
                continue;
            }
            TreeNode next;
            next.position = stepTowardsNeighbours(points[a], points, tree[a]);
            next.distance_to_top = node.distance_to_top + 1;
            next.skin_direction = node.skin_direction;
            next.roof_layers_below = node.roof_layers_below - 1;
            next.to_buildplate = placeBelow(plate_group_, radius(next.distance_to_top), next.position);
            next.sources = {group[a]};
            next.sources.insert(next.sources.end(), swallowed[a].begin(), swallowed[a].end());
            insertBelow(std::move(next));
        }
    }

    const TreeDropParams& p_;
    coord_um height_;
    TreeVolumes& volumes_;
    TreeLayers& layers_;
    int layer_;
    std::vector<TreeNode>& nodes_;
    bool plate_group_ = true;  ///< the group being dropped is the one going to the build plate
};

}  // namespace

void dropNodes(const TreeDropParams& params, coord_um layer_height_um, TreeVolumes& volumes,
               TreeLayers& layers) {
    for (int layer = static_cast<int>(layers.size()) - 1; layer > 0; --layer)
        LayerDrop(params, layer_height_um, volumes, layers, layer).run();
}

}  // namespace mixengine
