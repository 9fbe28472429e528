#include "toolpaths/support/SupportAreas.h"

#include <algorithm>
#include <cmath>

#include "common/ParallelFor.h"
#include "geometry/Angles.h"
#include "geometry/PolygonOps.h"
#include "toolpaths/core/LayerWindows.h"
#include "toolpaths/support/SupportSmoothing.h"

namespace mixengine {
namespace {

/// Where support may not be on layer n: the model grown by the xy distance.
Paths disallowedArea(const Paths& model, const Paths& own_overhang, const SupportAreaParams& p) {
    if (model.empty())
        return {};
    if (!p.z_overrides_xy || own_overhang.empty())
        return offsetPolygons(model, p.xy_distance_um);
    // Next to the layer's own overhang the smaller overhang distance is enough.
    const Paths away = differenceOf(model, offsetPolygons(own_overhang, p.xy_distance_um));
    return unionOf(offsetPolygons(model, p.xy_distance_overhang_um), offsetPolygons(away, p.xy_distance_um));
}

constexpr coord_um kSimplifyUm = 25;  // the model's outlines, once per layer
constexpr coord_um kCleanUm = 5;      // the propagated support, every layer (must not accumulate)
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

/// The band from `inner_um` inside the outlines to `outer_um` outside them (CuraEngine's tubeShape).
Paths tube(const Paths& outlines, coord_um inner_um, coord_um outer_um) {
    return differenceOf(offsetMiter(outlines, outer_um, kCuraMiterLimit),
                        offsetMiter(outlines, -inner_um, kCuraMiterLimit));
}

/// Per layer the model's slopes for the stair steps (see the header), summed over each step's layers.
std::vector<Paths> slopedAreas(const std::vector<Paths>& model, const SupportAreaParams& p, int threads) {
    const std::size_t n = model.size();
    std::vector<Paths> sloped(n);
    if (p.stair_layers <= 1)
        return sloped;
    const coord_um band = p.slope_band_um;
    parallelFor(n, threads, [&](std::size_t i) {
        if (i == 0)
            return;
        const Paths meet = intersectAll(tube(model[i - 1], band, 10), tube(model[i], 10, band));
        sloped[i] = offsetMiter(offsetMiter(meet, -10, kCuraMiterLimit), 10 + band, kCuraMiterLimit);
    });
    const std::size_t step = static_cast<std::size_t>(p.stair_layers);
    for (std::size_t i = 2; i < n; ++i) {
        if (i % step != 1)
            sloped[i] = unionOf(sloped[i], sloped[i - 1]);
    }
    return sloped;
}

/// The stair steps' removal carried down the layers (see the header).
class StairSteps {
  public:
    StairSteps(const std::vector<Paths>& model, const SupportAreaParams& p, int threads)
        : model_(model), p_(p), sloped_(slopedAreas(model, p, threads)) {}

    /// Layer i's support less the current step's removal.
    void cut(Paths& support, std::size_t i) const {
        if (p_.stair_layers > 1 && i >= gap() && !removal_.empty())
            support = differenceOf(support, removal_);
    }

    /// After layer i (every layer, with support or not): the removal for the layers below.
    void advance(std::size_t i) {
        const std::size_t gap = this->gap();
        const std::size_t step = static_cast<std::size_t>(std::max(1, p_.stair_layers));
        if (step <= 1 || i < gap || i % step != 0)
            return;
        const std::size_t bottom = i - gap;
        const Paths supporting = bottom >= 1 ? model_[bottom - 1] : Paths{};
        const Paths allowed =
            intersectAll(offsetMiter(supporting, p_.stair_width_um, kCuraMiterLimit), sloped_[i]);
        removal_ = bottom + 1 >= step ? intersectAll(model_[bottom + 1 - step], allowed) : allowed;
    }

  private:
    std::size_t gap() const { return static_cast<std::size_t>(std::max(0, p_.bottom_gap_layers)); }

    const std::vector<Paths>& model_;
    const SupportAreaParams& p_;
    std::vector<Paths> sloped_;
    Paths removal_;
};

/// Top-down: each layer's support is the layer above's plus the overhangs it must carry (and the
/// towers' roofs), joined (closing by the join distance), minus the model here and bottom_gap layers
/// below, simplified.
std::vector<Paths> propagateDown(const Overhangs& overhangs, const std::vector<Paths>& model,
                                 const std::vector<Paths>& blocked, const SupportAreaParams& p, int threads) {
    const std::vector<Paths>& full = overhangs.full;
    const std::size_t n = full.size();
    const bool towers = p.towers.max_supported_diameter_um > 0;
    TowerRoofs roofs(p.towers);
    StairSteps stairs(model, p, threads);
    std::vector<Paths> support(n);
    Paths current;
    for (std::size_t i = n; i-- > 0;) {
        const std::size_t source = i + static_cast<std::size_t>(p.top_gap_layers) + 1;
        if (p.conical_step_um != 0 && !current.empty())
            current = conicalStep(current, p);
        if (source < n && !full[source].empty())
            current = unionOf(current, full[source]);
        if (towers && i + 2 < n) {  // as CuraEngine: a roof starts one layer under its point
            roofs.startAt(pointsOf(overhangs, i + 1), pointsOf(overhangs, i));
            roofs.addTo(current);
        }
        if (current.empty()) {
            stairs.advance(i);
            continue;
        }
        if (p.join_distance_um > 0)  // as CuraEngine: its offsets bevel at a miter limit of 1.2
            current = offsetMiter(offsetMiter(current, p.join_distance_um, kCuraMiterLimit),
                                  -p.join_distance_um, kCuraMiterLimit);
        current = smoothOutward(current, kSmoothingAngleDegrees, p.smoothing_um);
        current = cleanPolygons(differenceOf(current, blocked[i]), kCleanUm);
        stairs.cut(current, i);
        stairs.advance(i);
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

/// An interface as CuraEngine 4.13 finishes it: grown by `offset_um` (a growth kept within `support`),
/// then its islands under `min_area_um2` dropped.
Paths finishInterface(Paths interface, const Paths& support, coord_um offset_um, double min_area_um2) {
    if (offset_um != 0 && !interface.empty()) {
        interface = offsetMiter(interface, offset_um, kCuraMiterLimit);
        if (offset_um > 0)
            interface = intersectAll(interface, support);
    }
    return min_area_um2 > 0 ? removeSmallIslands(interface, min_area_um2) : interface;
}

void splitInterfaces(std::vector<SupportLayerAreas>& out, const std::vector<Paths>& model,
                     const SupportAreaParams& p, int threads) {
    const int n = static_cast<int>(model.size());
    const int roof_window = p.roof_layers > 0 ? p.top_gap_layers + p.roof_layers : 0;
    const int floor_window = p.floor_layers > 0 ? p.bottom_gap_layers + p.floor_layers : 0;
    const std::vector<Paths> above = windowUnions(model, roof_window, threads);
    const std::vector<Paths> below = windowUnions(model, floor_window, threads);
    parallelFor(model.size(), threads, [&](std::size_t index) {
        const int i = static_cast<int>(index);
        SupportLayerAreas& layer = out[index];
        if (layer.support.empty())
            return;
        if (roof_window > 0 && i + 1 < n) {
            const std::size_t from = static_cast<std::size_t>(std::min(i + 1, std::max(0, n - roof_window)));
            layer.roof = finishInterface(intersectAll(layer.support, above[from]), layer.support,
                                         p.roof_offset_um, p.min_roof_area_um2);
        }
        if (floor_window > 0 && i > 0) {
            const std::size_t from = static_cast<std::size_t>(std::max(0, i - floor_window));
            layer.floor = differenceOf(finishInterface(intersectAll(layer.support, below[from]),
                                                       layer.support, 0, p.min_floor_area_um2),
                                       layer.roof);
        }
        layer.support = differenceOf(layer.support, unionOf(layer.roof, layer.floor));
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
        const coord_um allowed = std::max<coord_um>(0, std::llround(double(thickness) * slope));
        const Paths& here = layers[i].outlines;
        result.basic[i] = differenceOf(here, offsetPolygons(layers[i - 1].outlines, allowed));
        if (blockers && i < blockers->size() && !(*blockers)[i].empty())
            result.basic[i] = differenceOf(result.basic[i], (*blockers)[i]);
        if (!result.basic[i].empty())
            result.full[i] = intersectAll(offsetPolygons(result.basic[i], allowed + 100), here);
    });
    return result;
}

std::vector<SupportLayerAreas> computeSupportAreas(const std::vector<Paths>& model,
                                                   const Overhangs& overhangs, const SupportAreaParams& p,
                                                   int threads, const SupportMeshAreas& meshes) {
    const std::size_t n = model.size();
    std::vector<Paths> simple(n), blocked(n);
    parallelFor(n, threads, [&](std::size_t i) { simple[i] = cleanPolygons(model[i], kSimplifyUm); });
    const std::size_t gap = static_cast<std::size_t>(std::max(0, p.bottom_gap_layers));
    parallelFor(n, threads, [&](std::size_t i) {
        blocked[i] = gap > 0 && i >= gap ? unionOf(simple[i], simple[i - gap]) : simple[i];
    });
    const std::vector<Paths> propagated = propagateDown(overhangs, simple, blocked, p, threads);
    const std::vector<Paths> from_meshes = supportMeshSupport(meshes, blocked);
    std::vector<SupportLayerAreas> out(n);
    const std::size_t top = static_cast<std::size_t>(std::max(0, p.top_gap_layers));
    parallelFor(n, threads, [&](std::size_t i) {
        if (propagated[i].empty() && from_meshes[i].empty())
            return;
        Paths area = p.offset_um != 0 ? offsetMiter(propagated[i], p.offset_um) : propagated[i];
        if (!from_meshes[i].empty())
            area = unionOf(area, from_meshes[i]);
        area = differenceOf(area, disallowedArea(simple[i], overhangs.basic[i], p));
        if (top > 0 && i + top < n)  // the overhangs' extension must not reach into the top gap
            area = differenceOf(area, simple[i + top]);
        out[i].support = removeSmallIslands(area, p.min_area_um2);
    });
    if (p.buildplate_only)
        keepColumnsOnThePlate(out);
    removeFloating(out, threads);
    splitInterfaces(out, model, p, threads);
    return out;
}

}  // namespace mixengine
