#include "toolpaths/walls/OutlineGaps.h"

#include "geometry/PolygonOps.h"
#include "toolpaths/infill/LineInfill.h"

namespace mixengine {

Paths outlineGaps(const Paths& outlines, const Paths& outer_wall_region, coord_um outer_width_um,
                  coord_um outer_inset_um) {
    constexpr coord_um kSlackUm = 15;  // CuraEngine's perimeter_gaps_extra_offset
    const double min_area_um2 = 2.0 * double(outer_width_um) * double(outer_width_um);
    const Paths covered =
        outer_wall_region.empty()
            ? Paths{}
            : offsetMiter(outer_wall_region, outer_width_um / 2 + kSlackUm + outer_inset_um, Loops::United);
    return differenceWithoutSmallIslands(outlines, covered, min_area_um2);
}

std::vector<ExtrusionPath> outlineGapLines(const Paths& gaps, double angle_degrees,
                                           const FeatureStyle& style) {
    std::vector<ExtrusionPath> lines;
    if (gaps.empty() || style.width_um <= 0)
        return lines;
    for (const Path& line : lineSegments(gaps, style.width_um, angle_degrees, 0))
        lines.push_back(styledPath(line, false, Feature::Skin, style));
    return lines;
}

}  // namespace mixengine
