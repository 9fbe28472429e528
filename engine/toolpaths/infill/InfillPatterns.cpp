#include "toolpaths/infill/InfillPatterns.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "common/Error.h"
#include "geometry/Angles.h"
#include "geometry/Point.h"
#include "geometry/PointQueries.h"
#include "geometry/PolygonOps.h"
#include "slicing/OutlineCleanup.h"
#include "toolpaths/core/FeatureStyle.h"
#include "toolpaths/infill/ConnectedLines.h"
#include "toolpaths/infill/GyroidInfill.h"
#include "toolpaths/infill/InfillMultiplier.h"
#include "toolpaths/infill/LineInfill.h"
#include "toolpaths/infill/PolygonConnect.h"
#include "toolpaths/infill/ZigZag.h"

namespace mixengine {
namespace {

/// What a pattern draws: open lines and closed loops.
struct Drawn {
    Paths lines;
    Paths loops;
};

/// CuraEngine's shift of a line set at `angle` so that it passes through `origin`.
coord_um originShift(const Point2& origin, double angle_degrees) {
    if (origin.X == 0 && origin.Y == 0)
        return 0;
    const double r = radiansFromDegrees(angle_degrees);
    return static_cast<coord_um>(double(origin.X) * std::cos(r) - double(origin.Y) * std::sin(r));
}

LineSet lineSet(const InfillParams& p, coord_um spacing, double angle, coord_um own_shift) {
    return {spacing, angle, own_shift + p.shift_um + originShift(p.origin_um, angle)};
}

/// Two sets of lines 2d apart at `angle`, shifted symmetrically with z (tetrahedral patterns).
void appendHalfTetrahedral(std::vector<LineSet>& out, const InfillParams& p, double z_phase, double angle) {
    const coord_um period = 2 * p.line_distance_um;
    const double raw = std::numbers::sqrt2 / 2 * (double(p.z_um) + z_phase * double(period) * 2);
    coord_um shift = static_cast<coord_um>(raw) % period;
    shift = std::min(shift, period - shift);
    shift = std::min(shift, period / 2 - p.line_width_um / 2);
    shift = std::max(shift, p.line_width_um / 2);
    out.push_back(lineSet(p, period, angle, shift));
    out.push_back(lineSet(p, period, angle, -shift));
}

/// The line sets of the line-based patterns (empty for the others).
std::vector<LineSet> lineSetsOf(const InfillParams& p) {
    const coord_um d = p.line_distance_um;
    const double a = p.angle_degrees;
    std::vector<LineSet> sets;
    switch (p.pattern) {
        case InfillPattern::Lines:
            return {lineSet(p, d, a, 0)};
        case InfillPattern::Grid:
            return {lineSet(p, d, a, 0), lineSet(p, d, a + 90, 0)};
        case InfillPattern::Triangles:
        case InfillPattern::TriHexagon:
            return {lineSet(p, d, a, 0), lineSet(p, d, a + 60, 0),
                    lineSet(p, d, a + 120, p.pattern == InfillPattern::TriHexagon ? d / 2 : 0)};
        case InfillPattern::Cubic:
        case InfillPattern::CubicSubdiv: {
            const coord_um shift = static_cast<coord_um>(double(p.z_um) / std::numbers::sqrt2);
            return {lineSet(p, d, a, shift), lineSet(p, d, a + 120, shift), lineSet(p, d, a + 240, shift)};
        }
        case InfillPattern::Tetrahedral:
        case InfillPattern::QuarterCubic:
            appendHalfTetrahedral(sets, p, 0.0, a);
            appendHalfTetrahedral(sets, p, p.pattern == InfillPattern::QuarterCubic ? 0.5 : 0.0, a + 90);
            return sets;
        default:
            return sets;
    }
}

Paths concentricLoops(const Paths& area, const InfillParams& p) {
    Paths loops;
    // As CuraEngine: the gap to the area's edge is one line distance, like the gaps between loops.
    Paths ring = offsetMiter(area, -(p.line_distance_um - p.line_width_um / 2));
    while (!ring.empty()) {
        loops.insert(loops.end(), ring.begin(), ring.end());
        ring = offsetMiter(ring, -p.line_distance_um, Loops::United);
    }
    return loops;
}

/// Unconnected lines of every set, without the pieces shorter than w/5 (as CuraEngine).
Paths separateLines(const Paths& area, const std::vector<LineSet>& sets, coord_um line_width) {
    Paths out;
    const double min_length = double(line_width / 5);
    for (const LineSet& set : sets) {
        for (Path& line : lineSegments(area, set.spacing_um, set.angle_degrees, set.phase_um)) {
            const double length = distanceUm(line[1], line[0]);
            if (length >= min_length)
                out.push_back(std::move(line));
        }
    }
    return out;
}

/// `loops` simplified as CuraEngine 4.13 simplifies an infill pattern's polygons (simplify_resolution_um /
/// _deviation_um; both 0: kept); loops left with fewer than three vertices go.
Paths simplifiedLoops(Paths loops, const InfillParams& p) {
    return simplifyLoops(std::move(loops), p.simplify_resolution_um, p.simplify_deviation_um);
}

/// The cross fractal's curve cut to the area: the loops it encloses when connected, else its
/// pieces inside, each segment a line of its own (as CuraEngine).
Drawn crossPattern(const Paths& area, const InfillParams& p, bool connected) {
    Path curve = p.cross->curve(p.pattern == InfillPattern::Cross3d, p.z_um, p.line_width_um, p.pocket_um);
    if (curve.size() < 2)
        return {};
    Drawn drawn;
    if (connected) {
        drawn.loops = simplifiedLoops(intersectAll(area, {curve}), p);
        return drawn;
    }
    curve.push_back(curve.front());
    for (const Path& piece : clipLines({curve}, area)) {
        for (std::size_t i = 1; i < piece.size(); ++i)
            drawn.lines.push_back({piece[i - 1], piece[i]});
    }
    return drawn;
}

/// The segments of the trees whose root lies in the area (or within 5 µm of it, as CuraEngine moves
/// a root on the edge 5 µm in before it tests).
Paths lightningLines(const Paths& area, const InfillParams& p) {
    Paths lines;
    if (p.lightning_trees == nullptr || std::abs(areaUm2(area)) < double(p.line_width_um))
        return lines;
    constexpr double kEdgeMargin2 = 5.0 * 5.0;
    for (const LightningTreeLines& tree : *p.lightning_trees) {
        if (tree.segments.empty())
            continue;
        if (!insideArea(area, tree.root, true) &&
            nearestOnOutline(area, tree.root).distance2_um2 > kEdgeMargin2)
            continue;
        lines.insert(lines.end(), tree.segments.begin(), tree.segments.end());
    }
    return lines;
}

Drawn drawPattern(const Paths& area, const InfillParams& p, bool connected) {
    const coord_um d = p.line_distance_um;
    switch (p.pattern) {
        case InfillPattern::ZigZag: {
            const coord_um shift = p.shift_um + originShift(p.origin_um, p.angle_degrees);
            return {zigzagLines(area, d, p.angle_degrees, shift, p.zigzag_ends, p.zag_skip_count), {}};
        }
        case InfillPattern::Gyroid:
            return {
                gyroidCurves(area, static_cast<coord_um>(kGyroidPeriodPerLineDistance * double(d)), p.z_um),
                {}};
        case InfillPattern::Concentric:
            return {{}, simplifiedLoops(concentricLoops(area, p), p)};
        case InfillPattern::Cross:
        case InfillPattern::Cross3d:
            if (p.cross != nullptr)
                return crossPattern(area, p, connected);
            return {separateLines(area, {lineSet(p, d, p.angle_degrees, 0)}, p.line_width_um), {}};
        case InfillPattern::Lightning:
            return {lightningLines(area, p), {}};
        case InfillPattern::CubicSubdiv:
            if (p.subdiv_lines != nullptr)
                return {clipLines(*p.subdiv_lines, area), {}};
            return {separateLines(area, lineSetsOf(p), p.line_width_um), {}};
        default: {
            const std::vector<LineSet> sets = lineSetsOf(p);
            return {connected ? connectedLines(area, sets) : separateLines(area, sets, p.line_width_um), {}};
        }
    }
}

bool crossBased(InfillPattern pattern) {
    return pattern == InfillPattern::Cross || pattern == InfillPattern::Cross3d;
}

bool lineBased(InfillPattern pattern) {
    return pattern != InfillPattern::ZigZag && pattern != InfillPattern::Concentric &&
           pattern != InfillPattern::Gyroid && pattern != InfillPattern::CubicSubdiv &&
           !crossBased(pattern) && pattern != InfillPattern::Lightning;
}

/// Whether the pattern's lines are joined (CuraEngine's zig_zaggify, off for an even multiplier).
bool joinsLines(const InfillParams& p, bool even) {
    if (p.pattern == InfillPattern::ZigZag)
        return true;
    return p.connect_lines && !even &&
           (lineBased(p.pattern) || p.pattern == InfillPattern::Gyroid || crossBased(p.pattern));
}

Paths offsetArea(const Paths& area, coord_um delta, Loops loops) {
    return delta == 0 ? area : offsetMiter(area, delta, loops);
}

void appendPaths(const Paths& paths, bool closed, const InfillParams& p, std::vector<ExtrusionPath>& out) {
    const FeatureStyle style{p.line_width_um, p.speed_mm_s, p.flow, p.extruder};
    for (const Path& path : paths) {
        if (path.size() >= (closed ? 3U : 2U))
            out.push_back(styledPath(path, closed, p.feature, style));
    }
}

}  // namespace

InfillPattern infillPatternOf(const std::string& text, const std::string& key) {
    if (text == "lines")
        return InfillPattern::Lines;
    if (text == "cross")
        return InfillPattern::Cross;
    if (text == "cross_3d")
        return InfillPattern::Cross3d;
    if (text == "lightning")
        return InfillPattern::Lightning;
    if (text == "zigzag")
        return InfillPattern::ZigZag;
    if (text == "grid")
        return InfillPattern::Grid;
    if (text == "triangles")
        return InfillPattern::Triangles;
    if (text == "trihexagon")
        return InfillPattern::TriHexagon;
    if (text == "cubic")
        return InfillPattern::Cubic;
    if (text == "cubicsubdiv")
        return InfillPattern::CubicSubdiv;
    if (text == "tetrahedral")
        return InfillPattern::Tetrahedral;
    if (text == "quarter_cubic")
        return InfillPattern::QuarterCubic;
    if (text == "concentric")
        return InfillPattern::Concentric;
    if (text == "gyroid")
        return InfillPattern::Gyroid;
    throw InputError("setting '" + key + "': unknown pattern '" + text + "'");
}

std::vector<ExtrusionPath> generateInfill(const Paths& area, const InfillParams& params) {
    std::vector<ExtrusionPath> result;
    if (params.line_distance_um <= 0 || area.empty())
        return result;
    const coord_um w = params.line_width_um;
    const coord_um walls = params.wall_count * w;
    const bool even = params.multiplier > 1 && params.multiplier % 2 == 0;
    // As CuraEngine: an even multiplier draws the lines unconnected and connects its own loops.
    const bool connected = joinsLines(params, even);
    const bool octree = params.pattern == InfillPattern::CubicSubdiv && params.subdiv_lines != nullptr;
    const coord_um inset = octree ? 0 : walls + (connected ? w / 2 : 0);
    // Lightning's trees are cut to nothing: they are tested against the area as it is.
    const coord_um grow = params.pattern == InfillPattern::Lightning ? 0 : params.overlap_um - inset;
    Drawn drawn = drawPattern(offsetArea(area, grow, params.area_loops), params, connected);
    if (params.multiplier > 1) {
        // As CuraEngine: the cross patterns' outline keeps the overlap they added to it.
        const coord_um outline_inset = inset + (params.connect_lines && even ? w / 2 : 0) -
                                       (crossBased(params.pattern) ? params.overlap_um : 0);
        multiplyInfill(
            drawn.lines, drawn.loops, offsetArea(area, -outline_inset, params.area_loops),
            {params.multiplier, w, params.connect_lines, params.pattern == InfillPattern::Concentric});
    }
    Paths walls_loops;
    for (int wall = 0; wall < params.wall_count; ++wall) {
        const Paths loop = offsetMiter(area, -w / 2 - coord_um(wall) * w);
        if (loop.empty())
            break;  // the area is used up: no further wall fits (a huge count must not spin)
        walls_loops.insert(walls_loops.end(), loop.begin(), loop.end());
    }
    if (params.connect_polygons) {  // as CuraEngine: the pattern's loops, then the walls, joined
        drawn.loops.insert(drawn.loops.end(), walls_loops.begin(), walls_loops.end());
        appendPaths(connectLoops(drawn.loops, w), true, params, result);
    } else {
        appendPaths(walls_loops, true, params, result);
        appendPaths(drawn.loops, true, params, result);
    }
    appendPaths(drawn.lines, false, params, result);
    return result;
}

}  // namespace mixengine
