#include "toolpaths/adhesion/ExtruderSkirts.h"

#include "geometry/Clip.h"
#include "geometry/PolygonOps.h"
#include "toolpaths/core/FeatureStyle.h"
#include "toolpaths/support/Support.h"

namespace mixengine {

Paths areaInsideOutermost(const std::vector<ExtrusionPath>& lines) {
    Paths loops;
    for (const ExtrusionPath& line : lines) {
        if (line.closed && line.points.size() >= 3)
            loops.push_back(counterClockwise(line.points) ? line.points
                                                          : Path(line.points.rbegin(), line.points.rend()));
    }
    Paths outer;
    for (const Path& p : unionOf(loops)) {
        if (counterClockwise(p))
            outer.push_back(p);
    }
    return outer;
}

std::vector<ExtrusionPath> otherExtruderSkirts(const Settings& global, const std::vector<Settings>* extruders,
                                               const Paths& outermost, coord_um outer_width_um,
                                               int adhesion_extruder, const std::set<int>& used) {
    std::vector<ExtrusionPath> lines;
    if (outermost.empty())
        return lines;
    coord_um offset = 0;
    coord_um last_width = outer_width_um;
    for (int extruder : used) {
        if (extruder == adhesion_extruder)
            continue;
        const Settings& s = trainSettings(global, extruders, extruder);
        FeatureStyle style = featureStyle(
            s, {key::skirt_brim_line_width, key::skirt_brim_speed, key::skirt_brim_material_flow, {}}, 0);
        style.speed_mm_s = s.velocityMmPerS(key::skirt_brim_speed);  // not slowed down, as the skirt
        style.extruder = extruder;
        offset += last_width / 2 + style.width_um / 2;
        last_width = style.width_um;
        const double minimal_um = s.millimetres(key::skirt_brim_minimal_length) * 1000.0;
        double length_um = 0;
        constexpr int kMaxLines = 1000;  // a safety bound
        for (int n = 0; length_um < minimal_um && n < kMaxLines; ++n) {
            for (const Path& loop : offsetPolygons(outermost, offset)) {
                lines.push_back(styledPath(loop, true, Feature::Skirt, style));
                length_um += lengthUm(loop, true);
            }
            offset += style.width_um;
        }
    }
    return lines;
}

}  // namespace mixengine
