#include "toolpaths/SkinPaths.h"

#include "toolpaths/PolygonOps.h"

namespace mixengine {
namespace {

InfillParams fillParams(const SkinFillParams& p) {
    InfillParams fill;
    fill.pattern = p.pattern;
    fill.line_distance_um = p.style.width_um;
    fill.angle_degrees = p.angle_degrees;
    fill.z_um = p.z_um;
    fill.line_width_um = p.style.width_um;
    fill.feature = Feature::Skin;
    fill.speed_mm_s = p.style.speed_mm_s;
    fill.flow = p.style.flow;
    fill.extruder = p.style.extruder;
    return fill;
}

}  // namespace

std::vector<ExtrusionPath> generateSkinPaths(const Paths& area, const SkinFillParams& p) {
    std::vector<ExtrusionPath> out;
    if (area.empty() || p.style.width_um <= 0)
        return out;
    const InfillParams fill = fillParams(p);
    if (p.pattern == InfillPattern::Concentric)
        return generateInfill(area, fill);
    const coord_um w = p.style.width_um;
    Paths inside = area;
    for (int i = 0; i < p.outline_count && !inside.empty(); ++i) {
        const Paths loops = offsetMiter(inside, -w / 2);
        appendStyledLoops(loops, Feature::Skin, p.style, out);
        inside = loops.empty() ? Paths{} : offsetMiter(loops, -w / 2);
    }
    if (inside.empty())
        return out;
    for (ExtrusionPath& line : generateInfill(offsetMiter(inside, p.overlap_um), fill))
        out.push_back(std::move(line));
    return out;
}

}  // namespace mixengine
