#pragma once
// Infill patterns by Cura's names, all built from one line distance d (Cura's resolved
// infill_line_distance / support_line_distance / skin spacing, which already carries the pattern's
// multiplier: grid ×2, triangles/trihexagon/cubic ×3, tetrahedral/quarter_cubic ×2):
//   lines             — one line set at the angle, d apart;
//   zigzag            — the same lines joined along the area's edge (toolpaths/ZigZag.h);
//   grid              — line sets at angle and angle + 90°, each d apart;
//   triangles         — angle, +60°, +120°, each d apart, all through the origin;
//   trihexagon        — as triangles with the third set shifted by d/2;
//   cubic             — angle, +120°, +240°, each d apart, shifted by z/√2 so cubes build up;
//   tetrahedral, quarter_cubic — two directions of line pairs 2d apart, shifted with z;
//   concentric        — loops d apart, the first d − w/2 inside the area (its centre line one line
//                       distance from the edge of a line along the area's edge);
//   gyroid            — toolpaths/GyroidInfill.h with period 2.41·d.
// cubicsubdiv prints as cubic; cross, cross_3d and lightning print as lines at d (the same
// material per area, not the same shape).
#include <string>
#include <vector>

#include "geometry/Point.h"
#include "toolpaths/ExtrusionPath.h"

namespace mixengine {

enum class InfillPattern {
    Lines,
    ZigZag,
    Grid,
    Triangles,
    TriHexagon,
    Cubic,
    Tetrahedral,
    QuarterCubic,
    Concentric,
    Gyroid,
};

/// Cura's value → pattern; an unknown value is an InputError naming `key`.
InfillPattern infillPatternOf(const std::string& text, const std::string& key);

struct InfillParams {
    InfillPattern pattern = InfillPattern::Lines;
    coord_um line_distance_um = 0;  ///< 0 = nothing
    double angle_degrees = 45;
    coord_um z_um = 0;  ///< height of the layer (cubic, tetrahedral, gyroid)
    coord_um line_width_um = 400;
    Feature feature = Feature::Fill;
    double speed_mm_s = 60;
    double flow = 1.0;
    int extruder = 0;
    bool zigzag_end_pieces = false;  ///< zigzag: also print the area's ends (support_connect_zigzags)
};

/// The pattern's lines inside `area` (lines end on its boundary).
std::vector<ExtrusionPath> generateInfill(const Paths& area, const InfillParams& params);

}  // namespace mixengine
