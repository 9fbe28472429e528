#pragma once
// Where a mesh's sparse infill prints, at which density and how many layers thick, as CuraEngine
// 4.13 arranges it (SkinInfillAreaComputation) from every layer's infill area (toolpaths/skin/Skin.h).
// Layer indices are the mesh's sliced layers; n is their count. In order:
//
// 1. Infill as support (infill_support_enabled): from the second layer from the top down, a
//    layer keeps only the infill carrying the kept infill of the layer above, and the overhangs
//    of the layer above's infill area: its own infill area shrunk by support_reach_um (what the
//    layer below cannot carry at infill_support_angle) minus the area above, grown by the reach
//    + 50 µm, minus the area above again.
// 2. Gradual infill (gradual_infill_steps s, gradual_infill_step_height as gradual_step_layers
//    layers): on layers initial_bottom_layers … n − 1 − top_layers (elsewhere nothing), density k
//    (0 = densest) covers the part of the layer's infill that is not infill on every one of
//    layers i + k·step + skip … i + (k + 1)·step (skip = 1, or about 8 with
//    skin_no_small_gaps_heuristic, a divisor of the step); a step past the last layer counts as
//    no infill. The densities stop at the first step whose infill above is empty; the last density
//    covers the whole infill. (toolpaths/infill/MeshInfill.h gives density k its spacing.)
// 3. Combining (infill_sparse_thickness, as combine_layers N ≥ 2): on every layer i divisible by N
//    from the first such layer at or above initial_bottom_layers + N − 1 up to n − 1 − top_layers,
//    for c = 1 … N − 1 (layer i − c not below that first layer): the area at thickness c of each
//    density that is infill on layer i − c too (opened by 200 µm) moves to thickness c + 1 and
//    leaves layer i − c (its same density, and for the densest on layer i every sparser one below).
//    The lower layers print nothing there; layer i prints it c + 1 layers thick.
#include <vector>

#include "geometry/Point.h"

namespace mixengine {

struct InfillLayerParams {
    bool support_only = false;          ///< infill_support_enabled
    coord_um support_reach_um = 0;      ///< (tan(infill_support_angle) − 0.01) · layer_height
    int gradual_steps = 0;              ///< gradual_infill_steps
    int gradual_step_layers = 0;        ///< gradual_infill_step_height / layer_height, rounded
    bool small_gaps_heuristic = false;  ///< skin_no_small_gaps_heuristic
    int combine_layers = 1;             ///< infill_sparse_thickness / layer_height, rounded, ≥ 1
    int initial_bottom_layers = 0;
    int top_layers = 0;
};

/// One layer's infill: by_density[k][t] is the area of density k printed t + 1 layers thick.
/// by_density has at least one entry; the last is the sparsest and covers all single-thickness
/// infill of the layer.
struct LayerInfill {
    std::vector<std::vector<Paths>> by_density;
};

std::vector<LayerInfill> arrangeInfill(const std::vector<Paths>& infill_areas,
                                       const InfillLayerParams& params, int threads);

}  // namespace mixengine
