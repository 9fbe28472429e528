#pragma once
// Line infill: parallel lines `line_distance_um` apart, clipped to `area` (the lines end on its
// boundary; overlap with the walls is the caller's offset of the area).
//
// Direction and placement follow CuraEngine: at angle a the lines run along (sin a, cos a), so
// 0° is along Y and 45° is "/"; in the frame rotated by a they are the vertical lines
// x = shift + k·line_distance for every integer k, i.e. anchored to the build plate's origin, not
// to the area, so the same setting gives the same lines on every layer and in every part.
// The lines are returned as open two-point paths, sorted across the scan direction and alternating
// in direction (zig-zag order). The pieces inside are found from where the lines cross the area's
// edges, paired even-odd on each line (toolpaths/infill/ScanCrossings.h; the area is a united one), each
// end the crossing rounded to the micron — no Clipper pass, whose scan line would sweep every
// infill line at once.
#include <vector>

#include "geometry/Point.h"
#include "toolpaths/core/ExtrusionPath.h"

namespace mixengine {

struct LineInfillParams {
    coord_um line_distance_um = 0;  ///< 0 = no lines
    coord_um line_width_um = 400;
    double angle_degrees = 45;
    coord_um shift_um = 0;  ///< offset of the line grid across the lines
    Feature feature = Feature::Fill;
    double speed_mm_s = 60;
    double flow = 1.0;
    int extruder = 0;
};

std::vector<ExtrusionPath> generateLineInfill(const Paths& area, const LineInfillParams& params);

/// The same lines as bare polylines (no style), for patterns built from several line sets.
Paths lineSegments(const Paths& area, coord_um line_distance_um, double angle_degrees, coord_um shift_um);

}  // namespace mixengine
