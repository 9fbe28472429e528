#pragma once
// Walls: concentric insets of a layer's outlines.
//
// The outer wall's centre line lies wall_line_width_0 / 2 inside the outline (minus
// wall_0_inset); each further wall lies one wall_line_width_x further in. A part too thin for a
// wall simply gets fewer walls (an inset that vanishes is not emitted, so no zero-width walls).
#include <vector>

#include "geometry/Point.h"
#include "toolpaths/ExtrusionPath.h"

namespace mixengine {

struct WallParams {
    int wall_count = 2;
    coord_um outer_width_um = 400;
    coord_um inner_width_um = 400;
    coord_um outer_inset_um = 0;  ///< wall_0_inset
    double outer_speed_mm_s = 30;
    double inner_speed_mm_s = 60;
};

struct WallResult {
    std::vector<ExtrusionPath> walls;  ///< outer walls first, then inner ones, per island
    Paths inner_area;                  ///< the area inside the innermost wall (its inner edge)
};

WallResult generateWalls(const Paths& outlines, const WallParams& params);

/// Clipper offset of closed polygons by `delta_um` (negative = inwards), round joins.
Paths offsetPolygons(const Paths& polygons, coord_um delta_um);

}  // namespace mixengine
