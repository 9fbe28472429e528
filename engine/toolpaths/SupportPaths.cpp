#include "toolpaths/SupportPaths.h"

#include "toolpaths/PolygonOps.h"

namespace mixengine {
namespace {

void appendFill(const Paths& area, const SupportFill& fill, Feature feature, coord_um z,
                std::vector<ExtrusionPath>& out) {
    if (area.empty())
        return;
    const coord_um w = fill.style.width_um;
    Paths inside = area;
    for (int i = 0; i < fill.wall_count && !inside.empty(); ++i) {
        const Paths loops = offsetMiter(inside, -w / 2);
        appendStyledLoops(loops, feature, fill.style, out);
        inside = loops.empty() ? Paths{} : offsetMiter(loops, -w / 2);
    }
    InfillParams p;
    p.pattern = fill.pattern;
    p.line_distance_um = fill.line_distance_um;
    p.angle_degrees = fill.angle_degrees;
    p.z_um = z;
    p.line_width_um = w;
    p.feature = feature;
    p.speed_mm_s = fill.style.speed_mm_s;
    p.flow = fill.style.flow;
    p.extruder = fill.style.extruder;
    p.zigzag_end_pieces = fill.connect_zigzags;
    for (ExtrusionPath& path : generateInfill(inside, p))
        out.push_back(std::move(path));
}

}  // namespace

std::vector<ExtrusionPath> supportLayerPaths(const SupportLayerAreas& areas, const SupportLayerFills& fills,
                                             coord_um z_um) {
    std::vector<ExtrusionPath> out;
    appendFill(areas.floor, fills.floor, Feature::SupportInterface, z_um, out);
    appendFill(areas.support, fills.body, Feature::Support, z_um, out);
    appendFill(areas.roof, fills.roof, Feature::SupportInterface, z_um, out);
    return out;
}

}  // namespace mixengine
