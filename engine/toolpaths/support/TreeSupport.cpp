#include "toolpaths/support/TreeSupport.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/ParallelFor.h"
#include "geometry/Angles.h"
#include "geometry/PolygonOps.h"
#include "toolpaths/support/TreeNodes.h"

namespace mixengine {
namespace {

constexpr int kCircleCorners = 10;  // as CuraEngine
constexpr coord_um kFloorMarginUm = 10;
constexpr coord_um kCleanUm = 10;

coord_um ceilDiv(coord_um a, coord_um b) {
    return b <= 0 ? 0 : (a + b - 1) / b;
}

coord_um maxMoveUm(const Settings& g, coord_um layer_height) {
    const double angle = g.angleDegrees(key::support_tree_angle);
    if (angle >= 90)
        return std::numeric_limits<int>::max();
    return std::llround(std::tan(radiansFromDegrees(angle)) * double(layer_height));
}

int zLayers(const Settings& s, coord_um layer_height) {
    return static_cast<int>(ceilDiv(s.lengthMicrons(key::support_top_distance), layer_height)) + 1;
}

TreeVolumeParams volumeParams(const Settings& g, coord_um layer_height) {
    TreeVolumeParams p;
    p.xy_distance_um = g.lengthMicrons(key::support_xy_distance);
    p.xy_distance_overhang_um = g.lengthMicrons(key::support_xy_distance_overhang);
    p.z_overrides_xy = g.text(key::support_xy_overrides_z) == "z_overrides_xy";
    p.z_layers = zLayers(g, layer_height);
    p.max_move_um = maxMoveUm(g, layer_height);
    p.resolution_um = std::max<coord_um>(1, g.lengthMicrons(key::support_tree_collision_resolution));
    return p;
}

TreeContactParams contactParams(const Settings& s, coord_um layer_height) {
    TreeContactParams p;
    p.branch_distance_um = std::max<coord_um>(1, s.lengthMicrons(key::support_tree_branch_distance));
    p.z_layers = zLayers(s, layer_height);
    if (s.boolean(key::support_roof_enable))
        p.roof_layers =
            static_cast<int>((s.lengthMicrons(key::support_roof_height) + layer_height / 2) / layer_height);
    p.half_overhang_step_um = std::llround(std::tan(radiansFromDegrees(s.angleDegrees(key::support_angle))) *
                                           double(layer_height) / 2);
    return p;
}

double growthPerLayer(const Settings& g, coord_um layer_height, coord_um branch_radius) {
    const double angle = radiansFromDegrees(g.angleDegrees(key::support_tree_branch_diameter_angle));
    return std::sin(angle) * double(layer_height) / double(std::max<coord_um>(1, branch_radius));
}

TreeDropParams dropParams(const Settings& g, coord_um layer_height) {
    TreeDropParams p;
    p.max_move_um = maxMoveUm(g, layer_height);
    p.branch_radius_um = g.lengthMicrons(key::support_tree_branch_diameter) / 2;
    p.radius_growth_per_layer = growthPerLayer(g, layer_height, p.branch_radius_um);
    p.resolution_um = std::max<coord_um>(1, g.lengthMicrons(key::support_tree_collision_resolution));
    p.rests_on_model = g.text(key::support_type) == "everywhere";
    return p;
}

/// How nodes are drawn (see the header).
struct CircleStyle {
    coord_um radius_um = 1000;
    coord_um tip_radius_um = 300;
    int tip_layers = 0;
    double growth_per_layer = 0;
};

CircleStyle circleStyle(const Settings& g, coord_um layer_height) {
    CircleStyle c;
    c.radius_um = g.lengthMicrons(key::support_tree_branch_diameter) / 2;
    c.tip_radius_um = g.lengthMicrons(key::support_line_width) / 2 * 3 / 2;
    c.tip_layers = static_cast<int>(std::max<coord_um>(0, c.radius_um - c.tip_radius_um) / layer_height);
    c.growth_per_layer = growthPerLayer(g, layer_height, c.radius_um);
    return c;
}

Path nodeCircle(const TreeNode& node, const CircleStyle& c) {
    Path circle;
    const bool in_tip = node.distance_to_top < c.tip_layers;
    // In the tip the circle keeps its radius along the diagonal x = sign·y and shrinks to `across`
    // (of the radius) across it; below it grows linearly.
    const double across = in_tip ? (double(c.tip_radius_um) + double(node.distance_to_top) / c.tip_layers *
                                                                  double(c.radius_um - c.tip_radius_um)) /
                                       double(c.radius_um)
                                 : 1.0;
    const double grow = in_tip ? 1.0 : 1.0 + double(node.distance_to_top - c.tip_layers) * c.growth_per_layer;
    const double sign = node.skin_direction ? 1.0 : -1.0;
    for (int i = 0; i < kCircleCorners; ++i) {
        const double a = 2 * 3.14159265358979323846 * i / kCircleCorners;
        const double x = std::cos(a) * double(c.radius_um), y = std::sin(a) * double(c.radius_um);
        const double along = (x + sign * y) / 2, off = (x - sign * y) / 2;  // diagonal components
        const double px = (along + across * off) * grow, py = (sign * along - sign * across * off) * grow;
        circle.push_back({node.position.X + std::llround(px), node.position.Y + std::llround(py)});
    }
    return circle;
}

/// Floor: the body where it stands on the model (see the header).
Paths floorOf(const Paths& body, const std::vector<Paths>& model, int layer, const Settings& g,
              coord_um height) {
    const int gap = static_cast<int>(
        std::max<coord_um>(1, ceilDiv(g.lengthMicrons(key::support_bottom_distance), height)));
    const int skip = static_cast<int>(
        std::max<coord_um>(1, ceilDiv(g.lengthMicrons(key::support_interface_skip_height), height)));
    const int floor_layers = static_cast<int>(ceilDiv(g.lengthMicrons(key::support_bottom_height), height));
    Paths floor;
    auto sample = [&](int below) {
        const std::size_t at = static_cast<std::size_t>(std::max(0, layer - below - gap));
        floor = unionOf(floor, intersectAll(body, model[at]));
    };
    for (int below = 0; below < floor_layers; below += skip)
        sample(below);
    sample(floor_layers);
    return floor;
}

SupportLayerAreas drawLayer(const std::vector<TreeNode>& nodes, const CircleStyle& style) {
    Paths body, roof;
    for (const TreeNode& node : nodes) {
        if (node.removed)
            continue;
        (node.roof_layers_below > 0 ? roof : body).push_back(nodeCircle(node, style));
    }
    SupportLayerAreas out;
    out.roof = unionOf(roof);
    out.support = cleanPolygons(differenceOf(unionOf(body), out.roof), kCleanUm);
    return out;
}

}  // namespace

std::vector<SupportLayerAreas> treeSupportAreas(const Settings& g, const std::vector<TreeMesh>& meshes,
                                                const std::vector<Paths>& model, int threads) {
    const coord_um height = std::max<coord_um>(1, g.lengthMicrons(key::layer_height));
    std::vector<SupportLayerAreas> out(model.size());
    if (model.empty())
        return out;
    TreeVolumes volumes(&model, volumeParams(g, height));
    TreeLayers nodes(model.size());
    for (const TreeMesh& mesh : meshes)
        addContactPoints(*mesh.overhang, mesh.bounds, contactParams(*mesh.settings, height), volumes, nodes);
    dropNodes(dropParams(g, height), height, volumes, nodes);
    const CircleStyle style = circleStyle(g, height);
    const bool floors = g.boolean(key::support_bottom_enable);
    parallelFor(model.size(), threads, [&](std::size_t i) {
        out[i] = drawLayer(nodes[i], style);
        if (floors && !out[i].support.empty()) {
            out[i].floor = floorOf(out[i].support, model, static_cast<int>(i), g, height);
            if (!out[i].floor.empty())
                out[i].support = differenceOf(out[i].support, offsetMiter(out[i].floor, kFloorMarginUm));
        }
    });
    return out;
}

}  // namespace mixengine
