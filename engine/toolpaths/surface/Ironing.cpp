#include "toolpaths/surface/Ironing.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "geometry/PolygonOps.h"
#include "toolpaths/infill/LineInfill.h"
#include "toolpaths/infill/ZigZag.h"

namespace mixengine {
namespace {

/// angles[layer % n] of `key`, or the defaults when the list is empty.
double angleFor(const Settings& s, Key<SettingUnit::RealList> key, int layer,
                const std::vector<double>& defaults) {
    std::vector<double> angles = s.realList(key);
    if (angles.empty())
        angles = defaults;
    const int n = static_cast<int>(angles.size());
    return angles[static_cast<std::size_t>(((layer % n) + n) % n)];
}

long long countOf(const Settings& s, Key<SettingUnit::Integer> key) {
    return s.integer(key);
}

/// The top skin's angle on `layer` + 90°.
double ironingAngle(const Settings& s, int layer) {
    const double skin = angleFor(s, key::skin_angles, layer, {45, 135});
    const bool roofing = std::min(countOf(s, key::roofing_layer_count), countOf(s, key::top_layers)) > 0;
    return (roofing ? angleFor(s, key::roofing_angles, layer, {skin}) : skin) + 90.0;
}

/// The pattern's compensation of ironing_inset (see the header).
coord_um compensatedInset(const Settings& s, InfillPattern pattern, coord_um width_um) {
    const double inset = double(s.lengthMicrons(key::ironing_inset));
    const double w = double(width_um);
    const double flow = s.ratio(key::ironing_flow);
    if (pattern == InfillPattern::ZigZag) {
        const coord_um sparse = s.lengthMicrons(key::infill_sparse_thickness);
        const double scale = sparse > 0 ? double(s.lengthMicrons(key::layer_height)) / double(sparse) : 1.0;
        return static_cast<coord_um>(std::llround(inset - scale * w / 2 + flow * w / 2 + w / 2));
    }
    if (pattern == InfillPattern::Concentric)
        return static_cast<coord_um>(std::llround(inset + flow * w / 2));
    return static_cast<coord_um>(std::llround(inset));
}

/// A line's projection on CuraEngine's monotonic vector (−cos a, sin a) of lines at `angle_degrees`.
double acrossOf(const Point2& p, double angle_degrees) {
    const double a = angle_degrees * std::numbers::pi / 180.0;
    return -std::cos(a) * double(p.X) + std::sin(a) * double(p.Y);
}

/// Monotonic ironing: a polyline whose ends lie apart across the lines (a zigzag) starts at the end
/// further back, as CuraEngine's monotonic order prints it, whatever end the nozzle is nearer.
void startFurthestBack(ExtrusionPath& path, double angle_degrees, coord_um spacing_um) {
    const double front = acrossOf(path.points.front(), angle_degrees);
    const double back = acrossOf(path.points.back(), angle_degrees);
    if (std::abs(front - back) <= double(spacing_um))
        return;
    if (back < front)
        std::reverse(path.points.begin(), path.points.end());
    path.fixed_start = true;
}

/// Sorts `lines` across the direction of lines at `angle_degrees` (toolpaths/infill/LineInfill.h), along
/// CuraEngine's monotonic vector (−cos a, sin a).
void sortAcross(Paths& lines, double angle_degrees) {
    const double a = angle_degrees * std::numbers::pi / 180.0;
    const double across_x = -std::cos(a), across_y = std::sin(a);
    auto key = [&](const Path& line) {
        double lowest = std::numeric_limits<double>::max();
        for (const Point2& p : line)
            lowest = std::min(lowest, double(p.X) * across_x + double(p.Y) * across_y);
        return lowest;
    };
    std::stable_sort(lines.begin(), lines.end(),
                     [&](const Path& x, const Path& y) { return key(x) < key(y); });
}

Paths concentricLoops(const Paths& surface, coord_um first_inset_um, coord_um spacing_um) {
    Paths loops;
    Paths ring = offsetMiter(surface, -first_inset_um);
    while (!ring.empty() && spacing_um > 0) {
        loops.insert(loops.end(), ring.begin(), ring.end());
        ring = offsetMiter(ring, -spacing_um, Loops::United);
    }
    return loops;
}

}  // namespace

Paths topSurface(const Paths& outline, const Paths& outline_above) {
    if (outline.empty())
        return {};
    return outline_above.empty() ? unionOf(outline) : differenceOf(outline, outline_above);
}

IroningParams ironingParams(const Settings& s, int layer) {
    IroningParams p;
    const std::string pattern = s.text(key::ironing_pattern);
    p.pattern = pattern == "concentric" ? InfillPattern::Concentric
                : pattern == "lines"    ? InfillPattern::Lines
                                        : InfillPattern::ZigZag;
    p.line_spacing_um = s.lengthMicrons(key::ironing_line_spacing);
    p.angle_degrees = ironingAngle(s, layer);
    p.monotonic = s.boolean(key::ironing_monotonic);
    p.style.width_um = s.lengthMicrons(key::skin_line_width);
    p.style.speed_mm_s = layerSpeed(s, key::speed_ironing, layer);
    p.style.flow = s.ratio(key::ironing_flow);
    const int nr = s.extruderIndex(key::top_bottom_extruder_nr);
    p.style.extruder = nr >= 0 ? nr : ownExtruder(s);
    p.inset_um = compensatedInset(s, p.pattern, p.style.width_um);
    return p;
}

std::vector<ExtrusionPath> ironingPaths(const Paths& surface, const IroningParams& p) {
    std::vector<ExtrusionPath> out;
    if (surface.empty() || p.line_spacing_um <= 0 || p.style.width_um <= 0)
        return out;
    if (p.pattern == InfillPattern::Concentric) {
        appendStyledLoops(concentricLoops(surface, p.inset_um, p.line_spacing_um), Feature::Ironing, p.style,
                          out);
        return out;
    }
    const Paths area = offsetMiter(surface, -p.inset_um);
    Paths lines = p.pattern == InfillPattern::ZigZag
                      ? zigzagLines(area, p.line_spacing_um, p.angle_degrees, 0, ZigzagEnds::None)
                      : lineSegments(area, p.line_spacing_um, p.angle_degrees, 0);
    if (p.monotonic)
        sortAcross(lines, p.angle_degrees);
    for (const Path& line : lines) {
        if (line.size() < 2)
            continue;
        out.push_back(styledPath(line, false, Feature::Ironing, p.style));
        out.back().keep_order = p.monotonic;
        if (p.monotonic)
            startFurthestBack(out.back(), p.angle_degrees, p.line_spacing_um);
    }
    return out;
}

}  // namespace mixengine
