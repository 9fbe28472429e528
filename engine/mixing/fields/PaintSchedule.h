#pragma once
// Colour mode's painted regions of one mesh: each painted face's colour (a 3MF colour or base
// material, or a PrusaSlicer/OrcaSlicer extruder n, whose colour is the n-th of
// mixing_paint_colors, or when that is empty the n-th of mixing_channel_colors), the distinct
// colours as regions (mixing/fields/PaintedRegions.h, carried inward by mixing_paint_depth) and the mix
// solved for each region's colour; mixing_paint_blend, the width over which the edges between regions
// are feathered (mixing/fields/FeatheredPaint.h; 0: hard edges).
#include <memory>
#include <vector>

#include "mesh/Mesh.h"
#include "mixing/fields/PaintedRegions.h"
#include "mixing/setup/MixingSettings.h"

namespace mixengine {

struct MeshPaint {
    std::unique_ptr<PaintedRegions> regions;  ///< null: nothing painted
    std::vector<SolvedColor> colors;          ///< one per region
    coord_um blend_um = 0;                    ///< mixing_paint_blend: 0 = hard edges
};

/// `scope`: the mesh's settings (mixing_paint_depth, mixing_paint_blend, mixing_paint_colors);
/// `channel_colors` the group's mixing_channel_colors. InputError: a bad depth, a negative blend or an
/// extruder without a colour.
MeshPaint paintOf(const Mesh& mesh, const Settings& scope, const std::vector<Rgb>& channel_colors,
                  const PigmentModel& model);

}  // namespace mixengine
