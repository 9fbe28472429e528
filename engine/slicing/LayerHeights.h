#pragma once
// Where each layer is cut and printed.
//
// Layer 0 is printed at z = layer_height_0; layer n ≥ 1 at layer_height_0 + n·layer_height.
// The cut height depends on slicing_tolerance (Cura's setting of that name):
//   middle    — the middle of the layer's slab (layer 0: layer_height_0 / 2);
//   inclusive — the union of the cuts at the slab's top and bottom (see Slicer);
//   exclusive — the intersection of the cuts at the slab's top and bottom (see Slicer).
// Layer count = the number of cutting planes at or below z_max, as CuraEngine 4.13 counts:
// floor((z_max − layer_height_0 + layer_height/2) / layer_height) + 1; no layer when z_max is below
// the first plane (layer_height_0 / 2). Halves of odd micron heights are rounded down.
// Throws InputError when layer_height_0 or layer_height is not positive.
#include <vector>

#include "geometry/Point.h"

namespace mixengine {

enum class SlicingTolerance { Middle, Inclusive, Exclusive };

struct LayerZ {
    coord_um print_z = 0;   ///< nozzle height of the layer (top of its slab)
    coord_um bottom_z = 0;  ///< bottom of the slab
    coord_um slice_z = 0;   ///< where the model is cut (middle mode)
};

std::vector<LayerZ> computeLayerHeights(coord_um model_max_z, coord_um layer_height_0, coord_um layer_height);

}  // namespace mixengine
