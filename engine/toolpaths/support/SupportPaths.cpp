#include "toolpaths/support/SupportPaths.h"

#include <algorithm>

#include "geometry/PolygonOps.h"

namespace mixengine {
namespace {

/// The walls of `area`; returns the area inside them.
Paths appendWalls(const Paths& area, const SupportFill& fill, Feature feature,
                  std::vector<ExtrusionPath>& out) {
    const coord_um w = fill.style.width_um;
    Paths inside = area;
    for (int i = 0; i < fill.wall_count && !inside.empty(); ++i) {
        const Paths loops = offsetMiter(inside, -w / 2);
        appendStyledLoops(loops, feature, fill.style, out);
        inside = loops.empty() ? Paths{} : offsetMiter(loops, -w / 2, Loops::United);
    }
    return inside;
}

InfillParams infillParams(const SupportFill& fill, Feature feature, coord_um z) {
    const coord_um w = fill.style.width_um;
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
    p.zigzag_ends = fill.zigzag_ends;
    p.zag_skip_count = fill.zag_skip_count;
    p.connect_lines = fill.connect_lines;
    p.overlap_um = fill.overlap_um;
    p.cross = fill.cross;
    p.simplify_resolution_um = fill.simplify_resolution_um;
    p.simplify_deviation_um = fill.simplify_deviation_um;
    return p;
}

void appendInfill(const Paths& area, const InfillParams& p, std::vector<ExtrusionPath>& out) {
    if (area.empty())
        return;
    for (ExtrusionPath& path : generateInfill(area, p))
        out.push_back(std::move(path));
}

void appendFill(const Paths& area, const SupportFill& fill, Feature feature, coord_um z,
                std::vector<ExtrusionPath>& out) {
    if (area.empty())
        return;
    appendInfill(appendWalls(area, fill, feature, out), infillParams(fill, feature, z), out);
}

/// Density k of the last density `last` (see the header).
InfillParams densityOf(InfillParams p, std::size_t k, std::size_t last) {
    const coord_um spread = p.line_distance_um << (k + 1);
    p.shift_um = spread / 2;
    p.line_distance_um = k == last ? spread / 2 : spread;
    return p;
}

/// The infill of an area printed `layers` layers thick: as CuraEngine 4.13, its lines are laid out as
/// for a line `layers` times as wide (so they keep that much farther from the area's edge), and
/// printed with the body's width at `layers` times its flow.
void appendThickInfill(const Paths& area, InfillParams p, std::size_t layers,
                       std::vector<ExtrusionPath>& out) {
    if (area.empty())
        return;
    const coord_um width_um = p.line_width_um;
    p.line_width_um = width_um * static_cast<coord_um>(layers);
    p.flow *= double(layers);
    for (ExtrusionPath& path : generateInfill(area, p)) {
        path.width_um = width_um;
        out.push_back(std::move(path));
    }
}

/// The body with its arranged infill: thicker areas first, then the single-layer densities.
void appendArrangedFill(const Paths& area, const LayerInfill& arranged, const SupportFill& fill, coord_um z,
                        std::vector<ExtrusionPath>& out) {
    if (area.empty() || arranged.by_density.empty())
        return;
    const Paths inside = appendWalls(area, fill, Feature::Support, out);
    const InfillParams base = infillParams(fill, Feature::Support, z);
    if (base.line_distance_um <= 0 || inside.empty())
        return;
    const std::size_t last = arranged.by_density.size() - 1;
    std::size_t thickest = 0;
    for (const std::vector<Paths>& by_thickness : arranged.by_density)
        thickest = std::max(thickest, by_thickness.size());
    for (std::size_t t = 1; t < thickest; ++t) {
        for (std::size_t k = last + 1; k-- > 0;) {
            if (t >= arranged.by_density[k].size())
                continue;
            appendThickInfill(intersectAll(arranged.by_density[k][t], inside), densityOf(base, k, last),
                              t + 1, out);
        }
    }
    for (std::size_t k = last + 1; k-- > 0;)
        appendInfill(intersectAll(arranged.by_density[k][0], inside), densityOf(base, k, last), out);
}

}  // namespace

std::vector<ExtrusionPath> supportLayerPaths(const SupportLayerAreas& areas, const SupportLayerFills& fills,
                                             coord_um z_um, const LayerInfill* arranged) {
    std::vector<ExtrusionPath> out;
    appendFill(areas.floor, fills.floor, Feature::SupportBottom, z_um, out);
    if (arranged != nullptr)
        appendArrangedFill(areas.support, *arranged, fills.body, z_um, out);
    else
        appendFill(areas.support, fills.body, Feature::Support, z_um, out);
    appendFill(areas.roof, fills.roof, Feature::SupportInterface, z_um, out);
    return out;
}

}  // namespace mixengine
