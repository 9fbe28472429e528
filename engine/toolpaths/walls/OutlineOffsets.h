#pragma once
// The outline adjustments CuraEngine 4.13 makes before walls are planned:
//   xy_offset (xy_offset_layer_0 on layer 0) grows (positive) or shrinks the whole outline with
//   round joins; hole_xy_offset then grows (positive) or shrinks every hole on its own, with mitred
//   joins (CuraEngine's default offset). A hole grown this way can leave a band too narrow for
//   infill between the walls: that becomes a perimeter gap (toolpaths/MeshToolpaths.h).
#include "geometry/Point.h"

namespace mixengine {

/// `outlines` (outer contours counter-clockwise, holes clockwise) adjusted as above; microns.
Paths offsetOutlines(const Paths& outlines, coord_um xy_offset_um, coord_um hole_offset_um);

}  // namespace mixengine
