#include "toolpaths/infill/InfillLayers.h"

#include <algorithm>
#include <cmath>

#include "common/ParallelFor.h"
#include "geometry/PolygonOps.h"
#include "toolpaths/core/LayerWindows.h"

namespace mixengine {
namespace {

/// Step 1: the infill each layer keeps as support for the layers above. The overhangs depend on the
/// areas only (in parallel); the kept infill runs down from the top.
std::vector<Paths> supportingInfill(const std::vector<Paths>& areas, coord_um reach, int threads) {
    std::vector<Paths> overhang(areas.size());
    parallelFor(areas.size() > 0 ? areas.size() - 1 : 0, threads, [&](std::size_t below) {
        const Paths& inside_above = areas[below + 1];
        const Paths basic = differenceOf(offsetMiter(areas[below], -reach), inside_above);
        overhang[below] = differenceOf(offsetMiter(basic, reach + 50), inside_above);
    });
    std::vector<Paths> own = areas;
    for (std::size_t i = areas.size(); i-- > 1;) {
        const std::size_t below = i - 1;
        if (!areas[below].empty())
            own[below] = intersectAll(unionOf(own[i], overhang[below]), areas[below]);
    }
    return own;
}

/// The layers gradual infill looks at per step: every `skip`-th from the step's start.
double skipLayers(const InfillLayerParams& p) {
    const double skip = p.small_gaps_heuristic ? 8.0 : 1.0;
    const double steps = std::max(1.0, std::ceil(double(p.gradual_step_layers) / skip));
    return double(p.gradual_step_layers) / steps;
}

/// What gradual infill compares with: every layer's kept infill and, without the heuristic, the
/// intersection of each run of gradual_step_layers layers (toolpaths/core/LayerWindows.h).
struct Above {
    const std::vector<Paths>& own;
    std::vector<Paths> windows;  ///< [j]: layers j … j + step − 1; empty with the heuristic
};

/// The part of `infill` that stays infill on the layers of step `step` above layer `i`.
Paths infillAbove(Paths infill, const Above& above, int i, int step, const InfillLayerParams& p) {
    const std::size_t n = above.own.size();
    if (!p.small_gaps_heuristic) {  // the layers i + step·S + 1 … i + (step + 1)·S at once
        const std::size_t first = static_cast<std::size_t>(i + step * p.gradual_step_layers + 1);
        return first < n ? intersectAll(infill, above.windows[first]) : Paths{};
    }
    const double skip = skipLayers(p);
    const double first = i + step * p.gradual_step_layers + std::floor(skip);
    const double last = i + (step + 1) * p.gradual_step_layers;
    for (double upper = first; upper <= last && !infill.empty(); upper += skip) {
        if (upper >= double(n))
            return {};
        infill = intersectAll(infill, above.own[static_cast<std::size_t>(upper)]);
    }
    return infill;
}

/// Step 2: the densities of layer i.
LayerInfill densities(const Above& above, int i, const InfillLayerParams& p) {
    const int n = static_cast<int>(above.own.size());
    const Paths& infill = above.own[static_cast<std::size_t>(i)];
    LayerInfill layer;
    if (infill.empty() || i < p.initial_bottom_layers || i > n - 1 - p.top_layers) {
        layer.by_density.push_back({Paths{}});
        return layer;
    }
    Paths less_dense = infill;
    for (int step = 0; step < p.gradual_steps; ++step) {
        less_dense = infillAbove(std::move(less_dense), above, i, step, p);
        if (less_dense.empty())
            break;
        layer.by_density.push_back({differenceOf(infill, less_dense)});
    }
    layer.by_density.push_back({infill});
    return layer;
}

/// Step 3 for one density of layer `upper` and the layer `c` below it.
void combineDensity(LayerInfill& upper, std::size_t k, LayerInfill& lower, const Paths& lower_area,
                    std::size_t c) {
    std::vector<Paths>& by_thickness = upper.by_density[k];
    Paths thick = openPolygons(intersectAll(by_thickness[c - 1], lower_area), 200);
    by_thickness[c - 1] = differenceOf(by_thickness[c - 1], thick);
    const std::size_t last_lower = k + 1 == upper.by_density.size() ? lower.by_density.size() - 1 : k;
    for (std::size_t j = k; j <= last_lower && j < lower.by_density.size(); ++j)
        lower.by_density[j][0] = differenceOf(lower.by_density[j][0], thick);
    by_thickness.push_back(std::move(thick));
}

void combineLayers(std::vector<LayerInfill>& layers, const std::vector<Paths>& areas,
                   const InfillLayerParams& p, int threads) {
    const int n = static_cast<int>(layers.size());
    const int amount = p.combine_layers;
    if (amount <= 1 || n - 1 < p.top_layers)
        return;
    int min_layer = p.initial_bottom_layers + amount - 1;
    min_layer -= min_layer % amount;
    int max_layer = n - 1 - p.top_layers;
    max_layer -= max_layer % amount;
    if (max_layer < min_layer)
        return;
    const std::size_t groups = static_cast<std::size_t>((max_layer - min_layer) / amount + 1);
    parallelFor(groups, threads, [&](std::size_t g) {
        const int i = min_layer + static_cast<int>(g) * amount;
        LayerInfill& upper = layers[static_cast<std::size_t>(i)];
        for (int c = 1; c < amount && i - c >= min_layer; ++c) {
            const std::size_t below = static_cast<std::size_t>(i - c);
            for (std::size_t k = 0; k < upper.by_density.size(); ++k)
                combineDensity(upper, k, layers[below], areas[below], static_cast<std::size_t>(c));
        }
    });
}

}  // namespace

std::vector<LayerInfill> arrangeInfill(const std::vector<Paths>& areas, const InfillLayerParams& p,
                                       int threads) {
    const std::vector<Paths> own =
        p.support_only ? supportingInfill(areas, p.support_reach_um, threads) : areas;
    Above above{own, {}};
    if (p.gradual_steps > 0 && !p.small_gaps_heuristic)
        above.windows = windowIntersections(own, p.gradual_step_layers, threads);
    std::vector<LayerInfill> layers(areas.size());
    parallelFor(areas.size(), threads,
                [&](std::size_t i) { layers[i] = densities(above, static_cast<int>(i), p); });
    combineLayers(layers, areas, p, threads);
    return layers;
}

}  // namespace mixengine
