#include "toolpaths/InfillPatterns.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "common/Error.h"
#include "toolpaths/FeatureStyle.h"
#include "toolpaths/GyroidInfill.h"
#include "toolpaths/LineInfill.h"
#include "toolpaths/PolygonOps.h"
#include "toolpaths/ZigZag.h"

namespace mixengine {
namespace {

void appendLines(Paths& out, const Paths& area, coord_um distance, double angle, coord_um shift) {
    Paths lines = lineSegments(area, distance, angle, shift);
    out.insert(out.end(), std::make_move_iterator(lines.begin()), std::make_move_iterator(lines.end()));
}

/// Two sets of lines 2d apart at `angle`, shifted symmetrically with z (tetrahedral patterns).
void appendHalfTetrahedral(Paths& out, const Paths& area, const InfillParams& p, double z_phase,
                           double angle) {
    const coord_um period = 2 * p.line_distance_um;
    const double raw = std::numbers::sqrt2 / 2 * (double(p.z_um) + z_phase * double(period) * 2);
    coord_um shift = static_cast<coord_um>(raw) % period;
    shift = std::min(shift, period - shift);
    shift = std::min(shift, period / 2 - p.line_width_um / 2);
    shift = std::max(shift, p.line_width_um / 2);
    appendLines(out, area, period, angle, shift);
    appendLines(out, area, period, angle, -shift);
}

Paths concentricLoops(const Paths& area, const InfillParams& p) {
    Paths loops;
    // As CuraEngine: the gap to the area's edge is one line distance, like the gaps between loops.
    Paths ring = offsetMiter(area, -(p.line_distance_um - p.line_width_um / 2));
    while (!ring.empty()) {
        loops.insert(loops.end(), ring.begin(), ring.end());
        ring = offsetMiter(ring, -p.line_distance_um);
    }
    return loops;
}

Paths patternLines(const Paths& area, const InfillParams& p) {
    const coord_um d = p.line_distance_um;
    const double a = p.angle_degrees;
    Paths out;
    switch (p.pattern) {
        case InfillPattern::Lines:
            appendLines(out, area, d, a, 0);
            break;
        case InfillPattern::ZigZag:  // as CuraEngine: the connections run half a line inside
            out = zigzagLines(offsetMiter(area, -p.line_width_um / 2), d, a, 0, p.zigzag_end_pieces);
            break;
        case InfillPattern::Grid:
            appendLines(out, area, d, a, 0);
            appendLines(out, area, d, a + 90, 0);
            break;
        case InfillPattern::Triangles:
        case InfillPattern::TriHexagon:
            appendLines(out, area, d, a, 0);
            appendLines(out, area, d, a + 60, 0);
            appendLines(out, area, d, a + 120, p.pattern == InfillPattern::TriHexagon ? d / 2 : 0);
            break;
        case InfillPattern::Cubic: {
            const coord_um shift = static_cast<coord_um>(double(p.z_um) / std::numbers::sqrt2);
            for (double turn : {0.0, 120.0, 240.0})
                appendLines(out, area, d, a + turn, shift);
            break;
        }
        case InfillPattern::Tetrahedral:
        case InfillPattern::QuarterCubic:
            appendHalfTetrahedral(out, area, p, 0.0, a);
            appendHalfTetrahedral(out, area, p, p.pattern == InfillPattern::QuarterCubic ? 0.5 : 0.0, a + 90);
            break;
        case InfillPattern::Gyroid:
            out = gyroidCurves(area, static_cast<coord_um>(kGyroidPeriodPerLineDistance * double(d)), p.z_um);
            break;
        case InfillPattern::Concentric:
            break;
    }
    return out;
}

}  // namespace

InfillPattern infillPatternOf(const std::string& text, const std::string& key) {
    if (text == "lines" || text == "cross" || text == "cross_3d" || text == "lightning")
        return InfillPattern::Lines;
    if (text == "zigzag")
        return InfillPattern::ZigZag;
    if (text == "grid")
        return InfillPattern::Grid;
    if (text == "triangles")
        return InfillPattern::Triangles;
    if (text == "trihexagon")
        return InfillPattern::TriHexagon;
    if (text == "cubic" || text == "cubicsubdiv")
        return InfillPattern::Cubic;
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
    const bool loops = params.pattern == InfillPattern::Concentric;
    const Paths lines = loops ? concentricLoops(area, params) : patternLines(area, params);
    for (const Path& line : lines) {
        if (line.size() < 2)
            continue;
        result.push_back(styledPath(line, loops, params.feature,
                                    {params.line_width_um, params.speed_mm_s, params.flow, params.extruder}));
    }
    return result;
}

}  // namespace mixengine
