#pragma once
// The lines that fill a skin (or roofing) area: `outline_count` loops (skin_outline_count) of the
// style's width just inside the area, then the pattern at line distance = line width (solid)
// inside the innermost loop, its area grown by `overlap_um` (skin_overlap_mm) so that the lines
// reach into the loop or, without loops, into the walls. A concentric pattern is loops only.
#include <vector>

#include "geometry/Point.h"
#include "toolpaths/ExtrusionPath.h"
#include "toolpaths/FeatureStyle.h"
#include "toolpaths/InfillPatterns.h"

namespace mixengine {

struct SkinFillParams {
    int outline_count = 1;
    InfillPattern pattern = InfillPattern::Lines;
    double angle_degrees = 45;
    coord_um overlap_um = 0;
    coord_um z_um = 0;
    FeatureStyle style;
};

std::vector<ExtrusionPath> generateSkinPaths(const Paths& area, const SkinFillParams& params);

}  // namespace mixengine
