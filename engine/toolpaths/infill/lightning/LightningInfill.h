#pragma once
// Lightning infill (Cura's infill_pattern lightning), as CuraEngine 4.13 builds it
// (LightningGenerator): trees of lines that hold up only what lies above them, built once for a
// mesh from its top layer down, before the layers' toolpaths.
//
//   outline   — layer i's trees live in `outlines[i]`, the layer's infill area less the infill
//               walls (the caller's);
//   overhang  — what a layer must hold up: its outline shrunk by the wall reach (what the
//               outline itself holds up, layer_height·tan(lightning_infill_overhang_angle)) less
//               the outline of the layer above;
//   growing   — on each layer, from the top down: the trees carried from the layer above are
//               grown to hold up the layer's overhang and grounded again
//               (toolpaths/infill/lightning/TreeGrowth.h); a line holds up what lies within the
//               radius max(infill_line_distance, infill_line_width)/2 of its end;
//   carrying  — a copy of each tree goes one layer down, pruned by
//               layer_height·tan(lightning_infill_prune_angle), straightened by at most
//               layer_height·tan(lightning_infill_straightening_angle) and cut to the outline
//               there (toolpaths/infill/lightning/TreePropagation.h);
//   lines     — toolpaths/infill/lightning/TreeLines.h.
// The layers' outline grids, overhangs and overhang points are made on `threads` threads; the
// growth is one pass down the layers; the result depends on nothing but the input (not on the
// thread count). Measured: on the armadillo (Ender-3, 20 %) 3391 mm of filament where CuraEngine
// 4.13 uses 3369 mm, about 0.1-0.3 s more than lines.
#include <vector>

#include "geometry/Point.h"
#include "toolpaths/infill/lightning/TreeLines.h"

namespace mixengine {

struct LightningParams {
    coord_um radius_um = 0;      ///< max(infill_line_distance, infill_line_width) / 2
    coord_um wall_reach_um = 0;  ///< layer_height·tan(lightning_infill_overhang_angle)
    coord_um prune_um = 0;       ///< layer_height·tan(lightning_infill_prune_angle)
    coord_um straighten_um = 0;  ///< layer_height·tan(lightning_infill_straightening_angle)
    coord_um line_width_um = 400;
};

class LightningInfill {
  public:
    LightningInfill(const LightningParams& params, const std::vector<Paths>& outlines, int threads);

    /// The trees of layer i (nothing beyond the layers given).
    const std::vector<LightningTreeLines>& treesAt(std::size_t layer) const;

  private:
    std::vector<std::vector<LightningTreeLines>> layers_;
    std::vector<LightningTreeLines> none_;
};

}  // namespace mixengine
