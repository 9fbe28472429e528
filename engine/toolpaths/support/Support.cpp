#include "toolpaths/support/Support.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <string>

#include "common/ParallelFor.h"
#include "geometry/Angles.h"
#include "geometry/Clip.h"
#include "geometry/PolygonOps.h"
#include "toolpaths/infill/InfillLayers.h"
#include "toolpaths/infill/cross/CrossFill.h"
#include "toolpaths/infill/cross/DensityImage.h"
#include "toolpaths/support/SupportAreas.h"
#include "toolpaths/support/SupportPaths.h"
#include "toolpaths/support/TreeSupport.h"

namespace mixengine {
namespace {

int layersFor(coord_um distance_um, coord_um layer_height_um, bool round_up) {
    if (distance_um <= 0 || layer_height_um <= 0)
        return 0;
    return static_cast<int>(round_up ? (distance_um + layer_height_um - 1) / layer_height_um
                                     : (distance_um + layer_height_um / 2) / layer_height_um);
}

int extruderOf(const Settings& s, Key<SettingUnit::Extruder> key) {
    const int nr = s.extruderIndex(key);
    return nr < 0 ? 0 : nr;
}

/// The maximum diameter of what towers support, 0 when `s` turns towers off.
coord_um towerMaxDiameter(const Settings& s) {
    if (!s.boolean(key::support_use_towers))
        return 0;
    return std::max<coord_um>(0, s.lengthMicrons(key::support_tower_maximum_supported_diameter));
}

SupportTowerParams towerParams(const Settings& s, coord_um layer_height) {
    SupportTowerParams t;
    t.max_supported_diameter_um = towerMaxDiameter(s);
    if (t.max_supported_diameter_um == 0)
        return t;
    t.diameter_um = s.lengthMicrons(key::support_tower_diameter);
    const double slope = std::tan(radiansFromDegrees(s.angleDegrees(key::support_tower_roof_angle)));
    // A flat roof (0°) is the whole diameter at once.
    t.roof_step_um = slope > 1e-6 ? static_cast<coord_um>(double(layer_height) / slope) : t.diameter_um;
    return t;
}

/// The joined support's smoothing shortcut (toolpaths/support/SupportSmoothing.h): as CuraEngine, the widest
/// of the support line and, when on, the roof and floor lines.
coord_um smoothingDistance(const Settings& s) {
    coord_um widest = s.lengthMicrons(key::support_line_width);
    if (s.boolean(key::support_roof_enable))
        widest = std::max(widest, s.lengthMicrons(key::support_roof_line_width));
    if (s.boolean(key::support_bottom_enable))
        widest = std::max(widest, s.lengthMicrons(key::support_bottom_line_width));
    return widest;
}

/// The interfaces' layers (rounded, as CuraEngine: none below half a layer), margins, offsets and
/// minimum areas (toolpaths/support/SupportAreas.h).
void interfaceParams(const Settings& s, coord_um layer_height, SupportAreaParams& p) {
    if (s.boolean(key::support_roof_enable))
        p.roof_layers = layersFor(s.lengthMicrons(key::support_roof_height), layer_height, false);
    if (s.boolean(key::support_bottom_enable))
        p.floor_layers = layersFor(s.lengthMicrons(key::support_bottom_height), layer_height, false);
    p.interface_skip_layers =
        std::max(1, layersFor(s.lengthMicrons(key::support_interface_skip_height), layer_height, false));
    p.roof_line_width_um = s.lengthMicrons(key::support_roof_line_width);
    p.floor_line_width_um = s.lengthMicrons(key::support_bottom_line_width);
    p.roof_offset_um = s.lengthMicrons(key::support_roof_offset);
    p.floor_offset_um = s.lengthMicrons(key::support_bottom_offset);
    p.min_roof_area_um2 = s.real(key::minimum_roof_area) * 1e6;
    p.min_floor_area_um2 = s.real(key::minimum_bottom_area) * 1e6;
}

SupportAreaParams areaParams(const Settings& s, coord_um layer_height) {
    SupportAreaParams p;
    p.top_gap_layers = layersFor(s.lengthMicrons(key::support_top_distance), layer_height, true);
    p.bottom_gap_layers = layersFor(s.lengthMicrons(key::support_bottom_distance), layer_height, true);
    p.xy_distance_um = s.lengthMicrons(key::support_xy_distance);
    p.xy_distance_overhang_um = s.lengthMicrons(key::support_xy_distance_overhang);
    p.z_overrides_xy = s.text(key::support_xy_overrides_z) == "z_overrides_xy";
    p.buildplate_only = s.text(key::support_type) == "buildplate";
    p.join_distance_um = s.lengthMicrons(key::support_join_distance);
    p.offset_um = s.lengthMicrons(key::support_offset);
    p.min_area_um2 = s.real(key::minimum_support_area) * 1e6;
    if (s.boolean(key::support_conical_enabled)) {
        const double angle = s.angleDegrees(key::support_conical_angle);
        const double slope = std::tan(radiansFromDegrees(std::abs(angle))) - 0.01;
        const coord_um step =
            static_cast<coord_um>(slope * double(layer_height));  // truncated, as CuraEngine
        p.conical_step_um = angle > 0 ? -step : angle < 0 ? step : 0;
        p.conical_min_width_um = s.lengthMicrons(key::support_conical_min_width);
    }
    p.towers = towerParams(s, layer_height);
    p.smoothing_um = smoothingDistance(s);
    interfaceParams(s, layer_height, p);
    p.layer_height_um = layer_height;
    // as CuraEngine: steps of support_bottom_stair_step_height / layer_height + 1 layers
    p.stair_step_layers =
        static_cast<int>(std::max<coord_um>(0, s.lengthMicrons(key::support_bottom_stair_step_height)) /
                             std::max<coord_um>(1, layer_height) +
                         1);
    p.stair_step_width_um = s.lengthMicrons(key::support_bottom_stair_step_width);
    p.stair_min_slope_degrees = s.angleDegrees(key::support_bottom_stair_step_min_slope);
    return p;
}

/// angles[layer mod n] (layer may be negative: raft filler layers), or `fallback` for no angles.
double angleFor(const Settings& s, Key<SettingUnit::RealList> key, int layer, double fallback) {
    const std::vector<double> angles = s.realList(key);
    if (angles.empty())
        return fallback;
    const int n = static_cast<int>(angles.size());
    return angles[static_cast<std::size_t>(((layer % n) + n) % n)];
}

/// The keys of the support's roof or floor.
struct InterfaceKeys {
    Key<SettingUnit::Text> pattern;
    Key<SettingUnit::Millimetres> line_distance;
    Key<SettingUnit::RealList> angles;
    Key<SettingUnit::Millimetres> height;
    FeatureKeys style;
};

constexpr InterfaceKeys kRoofKeys{key::support_roof_pattern,
                                  key::support_roof_line_distance,
                                  key::support_roof_angles,
                                  key::support_roof_height,
                                  {key::support_roof_line_width, key::speed_support_roof,
                                   key::support_roof_material_flow, key::support_roof_extruder_nr}};
constexpr InterfaceKeys kFloorKeys{key::support_bottom_pattern,
                                   key::support_bottom_line_distance,
                                   key::support_bottom_angles,
                                   key::support_bottom_height,
                                   {key::support_bottom_line_width, key::speed_support_bottom,
                                    key::support_bottom_material_flow, key::support_bottom_extruder_nr}};

/// The interface's angle on `layer`: its angles in turn; none given, as CuraEngine 4.13: concentric
/// 0°, triangles 90°, else 45° and 135° in turn for an interface two layers thick or more, 90° for a
/// thinner one.
double interfaceAngle(const Settings& s, const InterfaceKeys& keys, InfillPattern pattern, int layer) {
    if (!s.realList(keys.angles).empty())
        return angleFor(s, keys.angles, layer, 0);
    if (pattern == InfillPattern::Concentric)
        return 0;
    if (pattern == InfillPattern::Triangles)
        return 90;
    if (s.lengthMicrons(keys.height) < 2 * s.lengthMicrons(key::layer_height))
        return 90;
    return (layer % 2 + 2) % 2 == 0 ? 45 : 135;
}

SupportFill fillFrom(const Settings& s, const InterfaceKeys& keys, int layer) {
    SupportFill fill;
    fill.pattern = infillPatternOf(s.text(keys.pattern), std::string(keys.pattern.name));
    fill.line_distance_um = s.lengthMicrons(keys.line_distance);
    fill.angle_degrees = interfaceAngle(s, keys, fill.pattern, layer);
    fill.style = featureStyle(s, keys.style, layer);
    return fill;
}

/// The body's cross pattern: the support's fractal, joined with zig_zaggify_support (as CuraEngine;
/// the other patterns' lines stay unjoined).
void attachCross(SupportFill& fill, const Settings& body, const CrossFill* cross) {
    if (fill.pattern != InfillPattern::Cross && fill.pattern != InfillPattern::Cross3d)
        return;
    fill.cross = cross;
    fill.connect_lines = body.boolean(key::zig_zaggify_support);
    fill.simplify_resolution_um = body.lengthMicrons(key::meshfix_maximum_resolution);
    fill.simplify_deviation_um = body.lengthMicrons(key::meshfix_maximum_deviation);
}

/// As CuraEngine 4.13: a roof on the first layer has a wall, and a dense one (lines closer than two
/// widths) is spread by initial_layer_line_width_factor.
void firstLayerRoof(const Settings& s, SupportFill& roof) {
    roof.wall_count = 1;
    if (roof.line_distance_um < 2 * s.lengthMicrons(key::support_roof_line_width))
        roof.line_distance_um =
            std::llround(double(roof.line_distance_um) * s.ratio(key::initial_layer_line_width_factor));
}

/// The fills of `layer`; −1 stands for the raft's filler layers.
SupportLayerFills layerFills(const SupportInput& in, int layer, const CrossFill* cross) {
    const Settings& g = *in.global;
    const Key<SettingUnit::Extruder> body_key =
        layer <= 0 ? key::support_extruder_nr_layer_0 : key::support_infill_extruder_nr;
    const int body_nr = extruderOf(g, body_key);
    const Settings& body = trainSettings(g, in.extruders, body_nr);
    SupportLayerFills fills;
    fills.body.pattern = infillPatternOf(body.text(key::support_pattern), "support_pattern");
    fills.body.line_distance_um = body.lengthMicrons(layer == 0 ? key::support_initial_layer_line_distance
                                                                : key::support_line_distance);
    fills.body.angle_degrees = angleFor(body, key::support_infill_angles, layer, 0);
    fills.body.zigzag_ends =
        body.boolean(key::support_connect_zigzags) ? ZigzagEnds::Connected : ZigzagEnds::Open;
    fills.body.connect_lines = body.boolean(key::zig_zaggify_support);
    if (body.boolean(key::support_skip_some_zags))
        fills.body.zag_skip_count =
            static_cast<int>(std::max<long long>(0, body.integer(key::support_zag_skip_count)));
    fills.body.wall_count = static_cast<int>(body.integer(key::support_wall_count));
    if (layer <= 0) {  // as CuraEngine: the first layer of support is a grid with one more wall
        if (fills.body.pattern == InfillPattern::Lines || fills.body.pattern == InfillPattern::ZigZag)
            fills.body.pattern = InfillPattern::Grid;
        fills.body.wall_count += 1;
    }
    // as CuraEngine: the body's infill overlaps its walls by infill_overlap_mm (none without walls)
    if (fills.body.wall_count > 0)
        fills.body.overlap_um = body.lengthMicrons(key::infill_overlap_mm);
    fills.body.style = featureStyle(
        body, {key::support_line_width, key::speed_support_infill, key::support_material_flow, body_key},
        layer);
    fills.body.style.extruder = body_nr;
    attachCross(fills.body, body, cross);
    if (in.raft)  // as CuraEngine: no initial_layer_line_width_factor for support under a raft
        fills.body.style.width_um = body.lengthMicrons(key::support_line_width);
    const Settings& roof = trainSettings(g, in.extruders, extruderOf(g, key::support_roof_extruder_nr));
    const Settings& floor = trainSettings(g, in.extruders, extruderOf(g, key::support_bottom_extruder_nr));
    fills.roof = fillFrom(roof, kRoofKeys, layer);
    if (layer == 0)
        firstLayerRoof(roof, fills.roof);
    fills.floor = fillFrom(floor, kFloorKeys, layer);
    return fills;
}

bool supportsOverhangs(const SupportMesh& mesh) {
    return mesh.role.printsAlone() && mesh.settings->boolean(key::support_enable);
}

/// Per layer the union of the outlines of the meshes `which` picks (empty vector: none picked).
template <typename Pick>
std::vector<Paths> outlinesOf(const SupportInput& in, Pick which, int threads) {
    std::vector<const SupportMesh*> picked;
    for (const SupportMesh& mesh : in.meshes) {
        if (which(mesh))
            picked.push_back(&mesh);
    }
    if (picked.empty())
        return {};
    std::vector<Paths> layers(in.heights->size());
    parallelFor(layers.size(), threads, [&](std::size_t i) {
        Paths all;
        for (const SupportMesh* mesh : picked) {
            if (i < mesh->layers->size())
                all.insert(all.end(), (*mesh->layers)[i].outlines.begin(), (*mesh->layers)[i].outlines.end());
        }
        layers[i] = unionOf(all);
    });
    return layers;
}

SupportMeshAreas supportMeshAreas(const SupportInput& in, int threads) {
    SupportMeshAreas areas;
    areas.drop_down = outlinesOf(
        in,
        [](const SupportMesh& m) {
            return m.role.support_mesh && m.settings->boolean(key::support_mesh_drop_down);
        },
        threads);
    areas.in_place = outlinesOf(
        in,
        [](const SupportMesh& m) {
            return m.role.support_mesh && !m.settings->boolean(key::support_mesh_drop_down);
        },
        threads);
    return areas;
}

/// The body's infill arrangement (toolpaths/infill/InfillLayers.h) as CuraEngine's gradual support
/// (gradual_support_infill_steps, every gradual_support_infill_step_height; its upper layers are
/// looked at about every 8 layers) and combined support layers (support_infill_sparse_thickness);
/// nullopt when neither is on.
std::optional<InfillLayerParams> arrangement(const Settings& body, coord_um layer_height) {
    const coord_um h = std::max<coord_um>(layer_height, 1);
    InfillLayerParams p;
    p.gradual_steps =
        static_cast<int>(std::max<long long>(0, body.integer(key::gradual_support_infill_steps)));
    p.gradual_step_layers = static_cast<int>(
        std::max<coord_um>(1, (body.lengthMicrons(key::gradual_support_infill_step_height) + h / 2) / h));
    p.small_gaps_heuristic = true;
    p.combine_layers = static_cast<int>(
        std::max<coord_um>(1, (body.lengthMicrons(key::support_infill_sparse_thickness) + h / 2) / h));
    if (p.gradual_steps <= 0 && p.combine_layers <= 1)
        return std::nullopt;
    return p;
}

/// The bodies' infill arrangement; empty when neither gradual support nor combined layers are on.
std::vector<LayerInfill> arrangedBodies(const std::vector<SupportLayerAreas>& areas, const Settings& body,
                                        coord_um layer_height, int threads) {
    const std::optional<InfillLayerParams> params = arrangement(body, layer_height);
    if (!params)
        return {};
    std::vector<Paths> bodies(areas.size());
    for (std::size_t i = 0; i < areas.size(); ++i)
        bodies[i] = areas[i].support;
    return arrangeInfill(bodies, *params, threads);
}

bool isTree(const SupportMesh& mesh) {
    return mesh.settings->text(key::support_structure) == "tree";
}

/// The mesh's overhang points (toolpaths/support/SupportTowers.h) added to `points`, with its towers on;
/// inset by half the outer wall's line width (its centre line, as CuraEngine), without walls half the support
/// line width.
void addOverhangPoints(const SupportMesh& mesh, const std::vector<Paths>& blockers,
                       std::vector<std::vector<Paths>>& points) {
    const Settings& s = *mesh.settings;
    const coord_um max_diameter = towerMaxDiameter(s);
    if (max_diameter == 0)
        return;
    const bool walls = s.integer(key::wall_line_count) > 0;
    const coord_um inset = s.lengthMicrons(walls ? key::wall_line_width_0 : key::support_line_width) / 2;
    const std::vector<std::vector<Paths>> own =
        detectOverhangPoints(*mesh.layers, max_diameter, inset, blockers.empty() ? nullptr : &blockers);
    for (std::size_t i = 0; i < own.size() && i < points.size(); ++i)
        points[i].insert(points[i].end(), own[i].begin(), own[i].end());
}

/// The overhangs of the meshes with support_enable and normal support, united per layer.
Overhangs collectOverhangs(const SupportInput& in, int threads) {
    Overhangs all;
    all.basic.resize(in.heights->size());
    all.full.resize(in.heights->size());
    all.points.resize(in.heights->size());
    const std::vector<Paths> blockers = outlinesOf(
        in, [](const SupportMesh& m) { return m.role.anti_overhang_mesh; }, threads);
    for (const SupportMesh& mesh : in.meshes) {
        if (!supportsOverhangs(mesh) || isTree(mesh))
            continue;
        const Overhangs own = detectOverhangs(mesh.print_outlines ? *mesh.print_outlines : *mesh.layers,
                                              *in.heights, mesh.settings->angleDegrees(key::support_angle),
                                              threads, blockers.empty() ? nullptr : &blockers);
        parallelFor(all.basic.size(), threads, [&](std::size_t i) {
            if (i >= own.basic.size())
                return;
            all.basic[i] = all.basic[i].empty() ? own.basic[i] : unionOf(all.basic[i], own.basic[i]);
            all.full[i] = all.full[i].empty() ? own.full[i] : unionOf(all.full[i], own.full[i]);
        });
        addOverhangPoints(mesh, blockers, all.points);
    }
    return all;
}

/// The support brim's loops inside `outline` (see the header); `outline` becomes what is left inside
/// them.
std::vector<ExtrusionPath> supportBrim(const Settings& s, int extruder, Paths& outline) {
    std::vector<ExtrusionPath> loops;
    const int count = static_cast<int>(s.integer(key::support_brim_line_count));
    if (outline.empty() || count <= 0)
        return loops;
    FeatureStyle style = featureStyle(s,
                                      {key::skirt_brim_line_width, key::skirt_brim_speed,
                                       key::skirt_brim_material_flow, key::support_infill_extruder_nr},
                                      0);
    style.speed_mm_s = s.velocityMmPerS(key::skirt_brim_speed);
    style.extruder = extruder;
    const coord_um w = std::max<coord_um>(style.width_um, 1);
    const double smallest_hole_um2 = 100.0 * double(w) * double(w);
    for (int i = 0; i < count; ++i) {
        Paths ring = offsetPolygons(outline, -(w / 2 + coord_um(i) * w));
        if (ring.empty())
            break;
        std::erase_if(ring, [&](const Path& p) {
            const double area = signedAreaUm2(p);
            return area < 0 && area > -smallest_hole_um2;
        });
        appendStyledLoops(ring, Feature::Skirt, style, loops);
    }
    outline = intersectAll(outline, offsetPolygons(outline, -coord_um(count) * w));
    return loops;
}

/// The model's layer-0 outlines (outer contours only with brim_outside_only, its holes left out).
Paths brimBase(const Paths& layer0, bool outside_only) {
    const Paths all = unionOf(layer0);
    if (!outside_only)
        return all;
    Paths outer;
    for (const Path& p : all) {
        if (counterClockwise(p))
            outer.push_back(p);
    }
    return outer;
}

}  // namespace

Paths brimCoveredArea(const Settings& global, const std::vector<Settings>* extruders, const Paths& layer0) {
    if (layer0.empty() || global.text(key::adhesion_type) != "brim")
        return {};
    const Settings& body =
        trainSettings(global, extruders, extruderOf(global, key::support_infill_extruder_nr));
    if (!body.boolean(key::brim_replaces_support))
        return {};
    const Settings& adhesion =
        trainSettings(global, extruders, extruderOf(global, key::adhesion_extruder_nr));
    const long long lines = std::max<long long>(0, adhesion.integer(key::brim_line_count));
    if (lines == 0)
        return {};
    const double width = double(adhesion.lengthMicrons(key::skirt_brim_line_width)) *
                         (adhesion.ratio(key::initial_layer_line_width_factor));
    const bool outside_only = adhesion.boolean(key::brim_outside_only);
    const Paths base = brimBase(layer0, outside_only);
    Paths covered = offsetPolygons(base, std::llround(width * double(lines + lines % 2)));
    if (outside_only)  // the support in the model's holes stays: no brim there
        covered = differenceOf(covered, differenceOf(base, unionOf(layer0)));
    return covered;
}

namespace {

Box2 meshBounds(const std::vector<SlicedLayer>& layers) {
    Paths all;
    for (const SlicedLayer& layer : layers)
        all.insert(all.end(), layer.outlines.begin(), layer.outlines.end());
    return boundsOf(all);
}

/// The bounding box (x, y) of the meshes other than infill meshes and support blockers (as CuraEngine,
/// support meshes count and support_offset does not); a mesh without a placed box counts with its
/// outlines' bounds.
Box2 supportedBounds(const SupportInput& in) {
    std::optional<Box2> all;
    for (const SupportMesh& mesh : in.meshes) {
        if (mesh.role.infill_mesh || mesh.role.anti_overhang_mesh)
            continue;
        const AABB3& b = mesh.role.bounds;
        const Box2 box = b.max.x > b.min.x || b.max.y > b.min.y ? Box2{b.min.x, b.min.y, b.max.x, b.max.y}
                                                                : meshBounds(*mesh.layers);
        all = all ? Box2{std::min(all->left, box.left), std::min(all->top, box.top),
                         std::max(all->right, box.right), std::max(all->bottom, box.bottom)}
                  : box;
    }
    return all.value_or(Box2{0, 0, 0, 0});
}

/// The support's cross fractal when the support infill extruder's support_pattern is cross (and
/// support_line_distance positive), over supportedBounds with its support_line_width; the density from
/// cross_support_density_image when it names an image.
std::unique_ptr<CrossFill> supportCrossFill(const SupportInput& in, const Settings& body) {
    const std::string pattern = body.text(key::support_pattern);
    const coord_um line_distance = body.lengthMicrons(key::support_line_distance);
    const coord_um line_width = body.lengthMicrons(key::support_line_width);
    if (!wantsCrossFill(pattern, line_distance, line_width))
        return nullptr;
    const Box2 box = supportedBounds(in);
    return std::make_unique<CrossFill>(
        box, line_distance, line_width,
        densityImageAt(body.text(key::cross_support_density_image), box, "cross_support_density_image"));
}

/// The tree support of the meshes with support_enable and support_structure tree
/// (toolpaths/support/TreeSupport.h); none: empty.
std::vector<SupportLayerAreas> treeAreas(const SupportInput& in, int threads) {
    std::vector<Overhangs> overhangs;
    std::vector<const SupportMesh*> trees;
    for (const SupportMesh& mesh : in.meshes) {
        if (!supportsOverhangs(mesh) || !isTree(mesh))
            continue;
        overhangs.push_back(detectOverhangs(mesh.print_outlines ? *mesh.print_outlines : *mesh.layers,
                                            *in.heights, mesh.settings->angleDegrees(key::support_angle),
                                            threads));
        trees.push_back(&mesh);
    }
    if (trees.empty())
        return {};
    std::vector<TreeMesh> meshes;
    for (std::size_t i = 0; i < trees.size(); ++i)
        meshes.push_back({trees[i]->settings, &overhangs[i].basic, meshBounds(*trees[i]->layers)});
    return treeSupportAreas(*in.global, meshes, *in.model, threads);
}

/// Normal support's areas united with tree support's, layer by layer.
std::vector<SupportLayerAreas> supportAreas(const SupportInput& in, coord_um layer_height, int threads) {
    const Settings& g = *in.global;
    const Settings& body = trainSettings(g, in.extruders, extruderOf(g, key::support_infill_extruder_nr));
    const bool normal = std::any_of(in.meshes.begin(), in.meshes.end(), [](const SupportMesh& m) {
        return (supportsOverhangs(m) && !isTree(m)) || m.role.support_mesh;
    });
    std::vector<SupportLayerAreas> areas =
        normal ? computeSupportAreas(*in.model, collectOverhangs(in, threads), areaParams(body, layer_height),
                                     threads, supportMeshAreas(in, threads))
               : std::vector<SupportLayerAreas>(in.heights->size());
    const std::vector<SupportLayerAreas> tree = treeAreas(in, threads);
    parallelFor(std::min(tree.size(), areas.size()), threads, [&](std::size_t i) {
        areas[i].support = unionOf(areas[i].support, tree[i].support);
        areas[i].roof = unionOf(areas[i].roof, tree[i].roof);
        areas[i].floor = unionOf(areas[i].floor, tree[i].floor);
    });
    return areas;
}

}  // namespace

const Settings& trainSettings(const Settings& global, const std::vector<Settings>* extruders, int nr) {
    if (extruders == nullptr || extruders->empty())
        return global;
    const std::size_t index = static_cast<std::size_t>(std::max(0, nr));
    return (*extruders)[std::min(index, extruders->size() - 1)];
}

SupportResult generateSupport(const SupportInput& in, int threads) {
    SupportResult result;
    std::vector<std::vector<ExtrusionPath>>& paths = result.paths;
    paths.resize(in.heights->size());
    bool wanted = false;
    for (const SupportMesh& mesh : in.meshes)
        wanted = wanted || supportsOverhangs(mesh) || mesh.role.support_mesh;
    if (!wanted)
        return result;
    const Settings& g = *in.global;
    const Settings& body = trainSettings(g, in.extruders, extruderOf(g, key::support_infill_extruder_nr));
    std::vector<SupportLayerAreas> areas = supportAreas(in, g.lengthMicrons(key::layer_height), threads);
    if (areas.empty())
        return result;
    if (!in.first_layer_exclusion.empty()) {  // brim_replaces_support
        areas[0].support = differenceOf(areas[0].support, in.first_layer_exclusion);
        areas[0].roof = differenceOf(areas[0].roof, in.first_layer_exclusion);
    }
    result.first_layer_area = unionOf(unionOf(areas[0].support, areas[0].roof), areas[0].floor);
    if (!in.raft && body.boolean(key::support_brim_enable))
        result.brim = supportBrim(body, extruderOf(g, key::support_infill_extruder_nr), areas[0].support);
    const std::vector<LayerInfill> arranged =
        arrangedBodies(areas, body, g.lengthMicrons(key::layer_height), threads);
    const std::unique_ptr<CrossFill> cross = supportCrossFill(in, body);
    parallelFor(paths.size(), threads, [&](std::size_t i) {
        const SupportLayerAreas& a = areas[i];
        if (a.support.empty() && a.roof.empty() && a.floor.empty())
            return;
        paths[i] = supportLayerPaths(a, layerFills(in, static_cast<int>(i), cross.get()),
                                     (*in.heights)[i].print_z, arranged.empty() ? nullptr : &arranged[i]);
    });
    if (in.raft && !paths.empty() && !paths[0].empty()) {
        result.filler = supportLayerPaths(areas[0], layerFills(in, -1, cross.get()), 0);
        paths[0].clear();
    }
    result.areas = std::move(areas);
    return result;
}

}  // namespace mixengine
