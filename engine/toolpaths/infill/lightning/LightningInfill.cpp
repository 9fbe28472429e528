#include "toolpaths/infill/lightning/LightningInfill.h"

#include <memory>

#include "common/ParallelFor.h"
#include "geometry/PolygonOps.h"
#include "toolpaths/infill/lightning/LightningForest.h"
#include "toolpaths/infill/lightning/OutlineGrid.h"
#include "toolpaths/infill/lightning/TreeGrowth.h"
#include "toolpaths/infill/lightning/TreePropagation.h"
#include "toolpaths/infill/lightning/UnsupportedPoints.h"

namespace mixengine {
namespace {

/// Cell of the grids the outline's edges and the trees' nodes are looked up in.
constexpr coord_um kLocatorCellUm = 4'000;

/// What each layer needs before the pass down: its outline's grid and its overhang's points.
struct LayerStart {
    std::unique_ptr<OutlineGrid> grid;
    std::vector<UnsupportedPoint> points;
};

std::vector<LayerStart> layerStarts(const LightningParams& params, const std::vector<Paths>& outlines,
                                    int threads) {
    std::vector<LayerStart> starts(outlines.size());
    parallelFor(outlines.size(), threads, [&](std::size_t i) {
        starts[i].grid = std::make_unique<OutlineGrid>(outlines[i], kLocatorCellUm);
        Paths overhang = offsetMiter(outlines[i], -params.wall_reach_um);
        if (i + 1 < outlines.size())
            overhang = differenceOf(overhang, outlines[i + 1]);
        starts[i].points = overhangPoints(overhang, *starts[i].grid, params.radius_um);
    });
    return starts;
}

}  // namespace

LightningInfill::LightningInfill(const LightningParams& params, const std::vector<Paths>& outlines,
                                 int threads)
    : layers_(outlines.size()) {
    if (outlines.empty() || params.radius_um <= 0)
        return;
    std::vector<LayerStart> starts = layerStarts(params, outlines, threads);
    const GrowthParams growth{params.radius_um, params.wall_reach_um, 2 * kLocatorCellUm, kLocatorCellUm};
    const PropagationParams carry{params.prune_um, params.straighten_um, kLocatorCellUm / 2,
                                  2 * kLocatorCellUm};
    LightningForest forest;
    for (std::size_t i = outlines.size(); i-- > 0;) {
        const std::vector<int> carried = forest.roots;
        UnsupportedPoints unsupported(std::move(starts[i].points), params.radius_um);
        growNewBranches(forest, unsupported, *starts[i].grid, growth);
        reconnectCarried(forest, carried, *starts[i].grid, growth);
        layers_[i] = treeLines(forest, params.line_width_um);
        if (i == 0)
            break;
        LightningForest below;
        for (int root : forest.roots)
            propagateTree(forest, root, outlines[i - 1], *starts[i - 1].grid, carry, below);
        forest = std::move(below);
        starts[i].grid.reset();
    }
}

const std::vector<LightningTreeLines>& LightningInfill::treesAt(std::size_t layer) const {
    return layer < layers_.size() ? layers_[layer] : none_;
}

}  // namespace mixengine
