#pragma once
// Outline gaps (fill_outline_gaps), as CuraEngine 4.13 finds and prints them: what of a layer's
// outline the outer wall does not cover — the outline less the outer wall's centre region grown by
// half the outer wall's width, wall_0_inset and 15 µm (CuraEngine's slack, so that rounding leaves
// no gaps everywhere) — without the pieces under 2 outer wall widths squared; a part too thin for a
// wall is a gap as a whole (it is kept, not dropped). Filled with lines one gap-line width apart
// (no overlap) at the skin's angle of the layer, printed after the walls of their part.
#include <vector>

#include "geometry/Point.h"
#include "toolpaths/core/ExtrusionPath.h"
#include "toolpaths/core/FeatureStyle.h"

namespace mixengine {

/// The gaps between `outlines` and the outer wall, whose centre region (all parts; a part without
/// wall has none) is `outer_wall_region`, its width `outer_width_um` (the layer's), wall_0_inset
/// `outer_inset_um`.
Paths outlineGaps(const Paths& outlines, const Paths& outer_wall_region, coord_um outer_width_um,
                  coord_um outer_inset_um);

/// The lines filling `gaps`: lines `style.width_um` apart at `angle_degrees` (CuraEngine's line
/// infill anchored at the origin, toolpaths/infill/LineInfill.h), Feature Skin in `style`.
std::vector<ExtrusionPath> outlineGapLines(const Paths& gaps, double angle_degrees,
                                           const FeatureStyle& style);

}  // namespace mixengine
