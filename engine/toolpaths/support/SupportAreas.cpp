#include "toolpaths/support/SupportAreas.h"

#include <algorithm>
#include <cmath>

#include "common/ParallelFor.h"
#include "geometry/Angles.h"
#include "geometry/PolygonOps.h"
#include "toolpaths/support/SupportSmoothing.h"
#include "toolpaths/support/SupportStairs.h"

namespace mixengine {
namespace {

/// Where support may not be on layer n: the model grown by the xy distance.
Paths disallowedArea(const Paths& model, const Paths& own_overhang, const SupportAreaParams& p) {
    if (model.empty())
        return {};
    if (!p.z_overrides_xy || own_overhang.empty())  // as CuraEngine: mitred
        return offsetMiter(model, p.xy_distance_um);
    // Next to the layer's own overhang the smaller overhang distance is enough.
    const Paths away = differenceOf(model, offsetPolygons(own_overhang, p.xy_distance_um));
    return unionOf(offsetPolygons(model, p.xy_distance_overhang_um), offsetPolygons(away, p.xy_distance_um));
}

constexpr coord_um kCleanUm = 5;  // the support meshes' support, every layer (must not accumulate)
// The model's outlines, once per layer, for speed (CuraEngine does not simplify them): a vertex within
// 25 µm of its neighbours' line goes. Straight-edged models keep every corner (their bevels included);
// on armadillo52k with support the support takes about 1.5 times as long without it.
constexpr coord_um kSimplifyUm = 25;
constexpr double kCuraMiterLimit = 1.2;
constexpr double kSmoothingAngleDegrees = 135;  // CuraEngine's: sharper notches are filled

/// Conical support: the support from above shrunk (or grown) by one layer's step, its parts
/// narrower than the minimum width kept as they are.
Paths conicalStep(const Paths& from_above, const SupportAreaParams& p) {
    const coord_um half = p.conical_min_width_um / 2;
    const Paths wide = offsetMiter(offsetMiter(from_above, -half), half + 20);
    const Paths narrow = differenceOf(from_above, wide);
    return unionOf(offsetMiter(from_above, p.conical_step_um), narrow);
}

/// The overhang points of `layer`, none when out of range.
std::vector<Paths> pointsOf(const Overhangs& o, std::size_t layer) {
    return layer < o.points.size() ? o.points[layer] : std::vector<Paths>{};
}

/// Towers under small support islands (toolpaths/support/SupportTowers.h), for layer i of n.
void startTowersUnderIslands(TowerRoofs& roofs, const std::vector<Paths>& support,
                             const std::vector<Paths>& model, std::size_t i, const SupportAreaParams& p) {
    const std::size_t look = TowerRoofs::kSmallIslandLookLayers;
    const std::size_t below = look + static_cast<std::size_t>(std::max(0, p.bottom_gap_layers));
    if (i + look < support.size() && i >= below)
        roofs.startUnderSmallIslands(support[i], support[i + look], model[i - below]);
}

/// The joined support of layer i without the model, as CuraEngine one after the other: the model on
/// the layer (not on the first layer), then what the model below keeps free: `stair` (StairSteps::
/// keptFree), without stairs the model bottom_gap layers down.
Paths withoutModel(const Paths& area, const std::vector<Paths>& model, std::size_t i, const Paths* stair,
                   const SupportAreaParams& p) {
    Paths out = i > 0 ? differenceOf(area, model[i]) : area;
    if (stair != nullptr)
        return stair->empty() ? out : differenceOf(out, *stair);
    const std::size_t gap = static_cast<std::size_t>(std::max(0, p.bottom_gap_layers));
    return gap > 0 && i >= gap ? differenceOf(out, model[i - gap]) : out;
}

/// Top-down: each layer's support is the layer above's plus the overhangs it must carry (and the
/// towers' roofs), joined (closing by the join distance, smoothed), minus the model here and
/// bottom_gap layers below (withoutModel).
std::vector<Paths> propagateDown(const Overhangs& overhangs, const std::vector<Paths>& model,
                                 const SupportAreaParams& p, StairSteps* stairs) {
    const std::vector<Paths>& full = overhangs.full;
    const std::size_t n = full.size();
    const bool towers = p.towers.max_supported_diameter_um > 0;
    TowerRoofs roofs(p.towers);
    std::vector<Paths> support(n);
    Paths current;
    for (std::size_t i = n; i-- > 0;) {
        const std::size_t source = i + static_cast<std::size_t>(p.top_gap_layers) + 1;
        if (p.conical_step_um != 0 && !current.empty())
            current = conicalStep(current, p);
        if (source < n)  // as CuraEngine: united even with nothing to add
            current = unionOf(current, full[source]);
        if (towers && i + 2 < n) {  // as CuraEngine: a roof starts one layer under its point
            roofs.startAt(pointsOf(overhangs, i + 1), pointsOf(overhangs, i));
            roofs.addTo(current);
        }
        const Paths stair = stairs != nullptr ? stairs->keptFree(i) : Paths{};  // every layer, top down
        if (current.empty())
            continue;
        if (p.join_distance_um > 0) {  // as CuraEngine: each offset unites first, mitred (limit 1.2)
            current = offsetMiter(current, p.join_distance_um);
            current = offsetMiter(current, -p.join_distance_um);
        }
        current = smoothOutward(current, kSmoothingAngleDegrees, p.smoothing_um);
        current = withoutModel(current, model, i, stairs != nullptr ? &stair : nullptr, p);
        support[i] = current;
        if (towers)
            startTowersUnderIslands(roofs, support, model, i, p);
    }
    return support;
}

/// Support that has support neither below nor above it is dropped (single-layer specks).
void removeFloating(std::vector<SupportLayerAreas>& layers, int threads) {
    std::vector<Paths> kept(layers.size());
    parallelFor(layers.size(), threads, [&](std::size_t i) {
        if (i == 0 || i + 1 >= layers.size() || layers[i].support.empty()) {
            kept[i] = layers[i].support;
            return;
        }
        kept[i] = intersectAll(layers[i].support, unionOf(layers[i - 1].support, layers[i + 1].support));
    });
    for (std::size_t i = 0; i < layers.size(); ++i)
        layers[i].support = std::move(kept[i]);
}

/// Per layer the model there and `bottom_gap_layers` below (what support meshes' support may not enter).
std::vector<Paths> blockedByModel(const std::vector<Paths>& model, int bottom_gap_layers, int threads) {
    std::vector<Paths> blocked(model.size());
    const std::size_t gap = static_cast<std::size_t>(std::max(0, bottom_gap_layers));
    parallelFor(model.size(), threads, [&](std::size_t i) {
        blocked[i] = gap > 0 && i >= gap ? unionOf(model[i], model[i - gap]) : model[i];
    });
    return blocked;
}

/// Top-down: the support meshes' areas, the drop-down ones carried down, less the model here and
/// bottom_gap layers below.
std::vector<Paths> supportMeshSupport(const SupportMeshAreas& meshes, const std::vector<Paths>& blocked) {
    const std::size_t n = blocked.size();
    std::vector<Paths> support(n);
    Paths current;
    for (std::size_t i = n; i-- > 0;) {
        if (i < meshes.drop_down.size() && !meshes.drop_down[i].empty())
            current = unionOf(current, meshes.drop_down[i]);
        if (!current.empty())
            current = cleanPolygons(differenceOf(current, blocked[i]), kCleanUm);
        support[i] = current;
        if (i < meshes.in_place.size() && !meshes.in_place[i].empty())
            support[i] = unionOf(support[i], differenceOf(meshes.in_place[i], blocked[i]));
    }
    return support;
}

void keepColumnsOnThePlate(std::vector<SupportLayerAreas>& layers) {
    for (std::size_t i = 1; i < layers.size(); ++i)
        layers[i].support = intersectAll(layers[i].support, layers[i - 1].support);
}

/// The layers CuraEngine 4.13 looks at for an interface `layers` thick, sampled every `skip`.
float interfaceStep(int layers, int skip) {
    const int scans = std::max(1, (layers - 1) / std::max(1, skip));
    return std::max(1.0f, float(layers - 1) / float(scans));
}

/// The model on the layers above layer i that its roof lies under (see the header).
Paths roofModel(const std::vector<Paths>& model, int i, const SupportAreaParams& p, float step) {
    const int n = static_cast<int>(model.size());
    const int top = std::min(n - 1, i + p.roof_layers + p.top_gap_layers);
    Paths near;
    for (float at = float(top); at > float(i + p.top_gap_layers); at -= step) {
        const Paths& outlines = model[static_cast<std::size_t>(std::lround(at))];
        near.insert(near.end(), outlines.begin(), outlines.end());
    }
    return near;
}

/// The model on the layers below layer i that its floor lies over (see the header).
Paths floorModel(const std::vector<Paths>& model, int i, const SupportAreaParams& p, float step) {
    const int first = std::max(0, i - p.floor_layers - p.bottom_gap_layers);
    Paths near;
    for (float at = float(first); std::lround(at) < i - p.bottom_gap_layers; at += step) {
        const Paths& outlines = model[static_cast<std::size_t>(std::lround(at))];
        near.insert(near.end(), outlines.begin(), outlines.end());
    }
    return near;
}

/// One interface of a layer, taken out of `support` (CuraEngine 4.13's generateSupportInterfaceLayer).
Paths takeInterface(Paths& support, const Paths& model_near, coord_um line_width_um, coord_um offset_um,
                    double min_area_um2) {
    if (model_near.empty())
        return {};
    Paths found = intersectAll(support, unionOf(model_near));
    if (found.empty())
        return {};
    found = intersectAll(offsetMiter(found, line_width_um, kCuraMiterLimit), support);
    if (offset_um != 0) {
        found = offsetMiter(found, offset_um, kCuraMiterLimit);
        if (offset_um > 0)  // the interface must not reach beyond the support
            found = intersectAll(found, support);
    }
    if (min_area_um2 > 0)
        found = removeSmallIslands(found, min_area_um2);
    if (!found.empty())
        support = differenceOf(support, found);
    return found;
}

void splitInterfaces(std::vector<SupportLayerAreas>& out, const std::vector<Paths>& model,
                     const SupportAreaParams& p, int threads) {
    const int n = static_cast<int>(model.size());
    const float roof_step = interfaceStep(p.roof_layers, p.interface_skip_layers);
    const float floor_step = interfaceStep(p.floor_layers, p.interface_skip_layers);
    parallelFor(model.size(), threads, [&](std::size_t index) {
        const int i = static_cast<int>(index);
        SupportLayerAreas& layer = out[index];
        if (layer.support.empty())
            return;
        if (p.roof_layers > 0 && i < n - p.top_gap_layers)
            layer.roof = takeInterface(layer.support, roofModel(model, i, p, roof_step), p.roof_line_width_um,
                                       p.roof_offset_um, p.min_roof_area_um2);
        if (p.floor_layers > 0 && i >= p.bottom_gap_layers)
            layer.floor = takeInterface(layer.support, floorModel(model, i, p, floor_step),
                                        p.floor_line_width_um, p.floor_offset_um, p.min_floor_area_um2);
    });
}

}  // namespace

Overhangs detectOverhangs(const std::vector<SlicedLayer>& layers, const std::vector<LayerZ>& heights,
                          double angle_degrees, int threads, const std::vector<Paths>* blockers) {
    Overhangs result;
    result.basic.resize(layers.size());
    result.full.resize(layers.size());
    const double slope = std::tan(radiansFromDegrees(std::clamp(angle_degrees, 0.0, 89.9))) - 0.01;
    parallelFor(layers.size(), threads, [&](std::size_t i) {
        if (i == 0 || layers[i].outlines.empty())
            return;
        const coord_um thickness = heights[i].print_z - heights[i - 1].print_z;
        // as CuraEngine: truncated; its offsets (Polygons::offset) unite first and are mitred
        const coord_um allowed = std::max<coord_um>(0, static_cast<coord_um>(double(thickness) * slope));
        const Paths& here = layers[i].outlines;
        result.basic[i] = differenceOf(here, offsetMiter(layers[i - 1].outlines, allowed));
        if (blockers && i < blockers->size() && !(*blockers)[i].empty())
            result.basic[i] = differenceOf(result.basic[i], (*blockers)[i]);
        if (!result.basic[i].empty())
            result.full[i] = intersectAll(offsetMiter(result.basic[i], allowed + 100), here);
    });
    return result;
}

std::vector<SupportLayerAreas> computeSupportAreas(const std::vector<Paths>& outlines,
                                                   const Overhangs& overhangs, const SupportAreaParams& p,
                                                   int threads, const SupportMeshAreas& meshes) {
    const std::size_t n = outlines.size();
    std::vector<Paths> model(n);
    parallelFor(n, threads, [&](std::size_t i) { model[i] = cleanPolygons(outlines[i], kSimplifyUm); });
    const StairParams stair_params{p.stair_step_layers, p.stair_step_width_um, p.stair_min_slope_degrees,
                                   p.bottom_gap_layers};
    const std::vector<Paths> sloped = slopedAreas(model, stair_params, p.layer_height_um, threads);
    StairSteps stairs(&model, &sloped, stair_params);
    const std::vector<Paths> propagated =
        propagateDown(overhangs, model, p, p.stair_step_layers > 1 ? &stairs : nullptr);
    const std::vector<Paths> from_meshes =
        meshes.drop_down.empty() && meshes.in_place.empty()
            ? std::vector<Paths>(n)
            : supportMeshSupport(meshes, blockedByModel(model, p.bottom_gap_layers, threads));
    std::vector<SupportLayerAreas> out(n);
    const std::size_t top = static_cast<std::size_t>(std::max(0, p.top_gap_layers));
    parallelFor(n, threads, [&](std::size_t i) {
        if (propagated[i].empty() && from_meshes[i].empty())
            return;
        Paths area = p.offset_um != 0 ? offsetMiter(propagated[i], p.offset_um) : propagated[i];
        if (!from_meshes[i].empty())
            area = unionOf(area, from_meshes[i]);
        area = differenceOf(area, disallowedArea(model[i], overhangs.basic[i], p));
        if (top > 0 && i + top < n)  // the overhangs' extension must not reach into the top gap
            area = differenceOf(area, model[i + top]);
        out[i].support = removeSmallIslands(area, p.min_area_um2);
    });
    if (p.buildplate_only)
        keepColumnsOnThePlate(out);
    removeFloating(out, threads);
    splitInterfaces(out, outlines, p, threads);  // the outlines as they are, as CuraEngine
    return out;
}

}  // namespace mixengine
