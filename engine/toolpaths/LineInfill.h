#pragma once
// Line infill: parallel lines `line_distance_um` apart at `angle_degrees`, clipped to `area`.
// The lines are returned as open two-point paths, alternating in direction (zig-zag order).
#include <vector>

#include "geometry/Point.h"
#include "toolpaths/ExtrusionPath.h"

namespace mixengine {

struct LineInfillParams {
    coord_um line_distance_um = 0;  ///< 0 = no infill
    coord_um line_width_um = 400;
    double angle_degrees = 45;
    Feature feature = Feature::Fill;
    double speed_mm_s = 60;
};

std::vector<ExtrusionPath> generateLineInfill(const Paths& area, const LineInfillParams& params);

}  // namespace mixengine
