#include "toolpaths/skin/SkinPaths.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/PointQueries.h"
#include "geometry/PolygonOps.h"
#include "slicing/OutlineCleanup.h"
#include "toolpaths/infill/LineInfill.h"
#include "toolpaths/infill/PolygonConnect.h"
#include "toolpaths/skin/MonotonicOrder.h"

namespace mixengine {
namespace {

constexpr coord_um kInsetSlackUm = 10;  // CuraEngine's first skin loop: 10 µm less far in
constexpr coord_um kGapSlackUm = 15;    // and its perimeter gaps: 15 µm of slack against slivers

/// Where one skin part's paths go, and the sequence numbers handed out so far.
struct SkinOutput {
    std::vector<ExtrusionPath>& paths;
    Paths gaps;  ///< left by concentric fills
    std::uint32_t sequences = 0;
    std::uint32_t parts = 0;  ///< skin parts numbered so far
};

/// Marks the paths from `from` on as stage `stage` of skin part `part` (ExtrusionPath::skin_part).
void markStage(std::vector<ExtrusionPath>& paths, std::size_t from, std::uint32_t part, std::uint8_t stage) {
    for (std::size_t i = from; i < paths.size(); ++i) {
        paths[i].skin_part = part;
        paths[i].skin_stage = stage;
    }
}

/// `loops` simplified with the params' resolution and deviation (both 0: kept); loops left with fewer
/// than three vertices go.
Paths simplified(Paths loops, const SkinPathParams& p) {
    return simplifyLoops(std::move(loops), p.simplify_resolution_um, p.simplify_deviation_um);
}

/// `count` loops inside `part`, each simplified before the next is taken; `inner` becomes the area
/// inside the innermost one (the whole part when none fits).
Paths skinLoops(const Paths& part, const SkinPathParams& p, Paths& inner) {
    const coord_um width_um = p.skin.style.width_um;
    Paths loops, last;
    for (int i = 0; i < p.outline_count; ++i) {
        // `part` is an island of splitIslands' union: united.
        Paths ring = simplified(i == 0 ? offsetMiter(part, -width_um / 2 + kInsetSlackUm, Loops::United)
                                       : offsetMiter(last, -width_um, Loops::United),
                                p);
        if (ring.empty())
            break;
        loops.insert(loops.end(), ring.begin(), ring.end());
        last = std::move(ring);
    }
    inner = last.empty() ? part : offsetMiter(last, -width_um / 2, Loops::United);
    return loops;
}

/// Loops one line width apart, the first (w/2 − overlap) inside `area`; what they leave uncovered
/// is added to `gaps` when that is wanted.
Paths concentricLoops(const Paths& area, const SkinFillParams& fill, Paths* gaps) {
    const coord_um w = fill.style.width_um;
    Paths loops;
    Paths ring = offsetMiter(area, fill.overlap_um - w / 2);
    if (gaps)
        *gaps = unionOf(*gaps, differenceOf(area, offsetMiter(ring, w / 2 + kGapSlackUm, Loops::United)));
    while (!ring.empty()) {
        loops.insert(loops.end(), ring.begin(), ring.end());
        Paths next = offsetMiter(ring, -w, Loops::United);
        if (gaps)
            *gaps = unionOf(*gaps, differenceOf(offsetMiter(ring, -w / 2 - kGapSlackUm, Loops::United),
                                                offsetMiter(next, w / 2, Loops::United)));
        ring = std::move(next);
    }
    return loops;
}

InfillParams patternParams(const SkinFillParams& fill, coord_um z_um) {
    InfillParams p;
    p.pattern = fill.pattern;
    p.line_distance_um = static_cast<coord_um>(double(fill.style.width_um) / fill.density);
    p.angle_degrees = fill.angle_degrees;
    p.z_um = z_um;
    p.line_width_um = fill.style.width_um;
    p.feature = fill.feature;
    p.speed_mm_s = fill.style.speed_mm_s;
    p.flow = fill.style.flow;
    p.extruder = fill.style.extruder;
    p.connect_polygons = fill.connect_polygons;
    return p;
}

/// The open lines of `lines` as one sequence in monotonic order (loops stay as they are, first).
void appendMonotonic(std::vector<ExtrusionPath> lines, const SkinFillParams& fill, SkinOutput& out) {
    Paths open;
    for (ExtrusionPath& path : lines) {
        if (path.closed)
            out.paths.push_back(std::move(path));
        else
            open.push_back(std::move(path.points));
    }
    const std::uint32_t sequence = ++out.sequences;
    const coord_um max_adjacent = fill.style.width_um * 11 / 10;
    for (const Path& line : monotonicOrder(std::move(open), fill.angle_degrees, max_adjacent)) {
        ExtrusionPath path = styledPath(line, false, fill.feature, fill.style);
        path.sequence = sequence;
        out.paths.push_back(std::move(path));
    }
}

/// The vertex of `area` nearest to `target` (the first of equals).
Point2 nearestVertex(const Paths& area, const Point2& target) {
    Point2 best = area.front().front();
    double best_distance = -1;
    for (const Path& loop : area) {
        for (const Point2& p : loop) {
            const double d = distance2(p, target);
            if (best_distance < 0 || d < best_distance)
                best_distance = d, best = p;
        }
    }
    return best;
}

/// CuraEngine's two candidates for where a fill of lines at `angle_degrees` starts away from the
/// seam: the vertices of `area` nearest to the two points far out from its bounding box's middle,
/// on either side, across the lines' direction.
std::array<Point2, 2> seamAvoidingStarts(const Paths& area, double angle_degrees) {
    const Box2 box = boundsOf(area);
    const Point2 middle{(box.left + box.right) / 2, (box.top + box.bottom) / 2};
    const double reach = std::hypot(double(box.right - middle.X), double(box.bottom - middle.Y)) * 100;
    const double turn = double((90 - static_cast<int>(angle_degrees)) % 360) * std::numbers::pi / 180;
    const Point2 across{static_cast<coord_um>(-reach * std::sin(turn)),
                        static_cast<coord_um>(reach * std::cos(turn))};
    return {nearestVertex(area, {middle.X + across.X, middle.Y + across.Y}),
            nearestVertex(area, {middle.X - across.X, middle.Y - across.Y})};
}

/// Whether CuraEngine starts a fill away from the seam: lines not in monotonic order, the layer's
/// top/bottom pattern (what it checks, also for roofing) lines or zigzag.
bool startsAwayFromSeam(const SkinFillParams& fill, const SkinPathParams& params) {
    const InfillPattern layer_pattern = params.skin.pattern;
    return !fill.monotonic &&
           (layer_pattern == InfillPattern::Lines || layer_pattern == InfillPattern::ZigZag);
}

void appendFill(const Paths& area, const SkinFillParams& fill, const SkinPathParams& params,
                SkinOutput& out) {
    if (area.empty())
        return;
    if (fill.pattern == InfillPattern::Concentric) {
        Paths loops = simplified(concentricLoops(area, fill, params.gap_style ? &out.gaps : nullptr), params);
        if (fill.connect_polygons)
            loops = connectLoops(loops, fill.style.width_um);
        appendStyledLoops(loops, fill.feature, fill.style, out.paths);
        return;
    }
    std::vector<ExtrusionPath> lines =
        generateInfill(offsetMiter(area, fill.overlap_um, Loops::United), patternParams(fill, params.z_um));
    if (fill.monotonic) {
        appendMonotonic(std::move(lines), fill, out);
        return;
    }
    const std::optional<std::array<Point2, 2>> starts =
        startsAwayFromSeam(fill, params) && !area.front().empty()
            ? std::optional<std::array<Point2, 2>>(seamAvoidingStarts(area, fill.angle_degrees))
            : std::nullopt;
    for (ExtrusionPath& line : lines) {
        line.seam_avoiding_starts = starts;
        out.paths.push_back(std::move(line));
    }
}

void appendGapLines(const Paths& gaps, const SkinPathParams& params, std::vector<ExtrusionPath>& out) {
    if (gaps.empty() || !params.gap_style || params.gap_style->width_um <= 0)
        return;
    const FeatureStyle& style = *params.gap_style;
    const Paths area = offsetMiter(gaps, params.skin.overlap_um, Loops::United);
    for (const Path& line : lineSegments(area, style.width_um, params.gap_angle_degrees, 0))
        out.push_back(styledPath(line, false, Feature::Skin, style));
}

void appendSkinPart(const Paths& part, const Paths& roofing_area, const SkinPathParams& p, SkinOutput& out) {
    const bool skin_concentric = p.skin.pattern == InfillPattern::Concentric;
    const bool roof_concentric = p.roofing.pattern == InfillPattern::Concentric;
    const bool roofed = !roofing_area.empty() && !intersectAll(part, roofing_area).empty();
    // As CuraEngine: no loops around a concentric skin, unless its roofing is of another pattern.
    const bool loops_wanted = !skin_concentric || (roofed && !p.first_layer && !roof_concentric);
    Paths inner = part;
    Paths loops = loops_wanted ? skinLoops(part, p, inner) : Paths{};
    Paths roof_fill = roofed ? intersectAll(inner, roofing_area) : Paths{};
    Paths skin_fill = roofed ? differenceOf(inner, roofing_area) : inner;
    if (!loops.empty() && skin_fill.empty() && !roof_fill.empty() && roof_concentric && !p.first_layer) {
        loops.clear();  // all roofing, concentric: its loops replace the skin's
        roof_fill = intersectAll(part, roofing_area);
    }
    const std::uint32_t number = ++out.parts;
    std::size_t stage_start = out.paths.size();
    appendStyledLoops(loops, Feature::Skin, p.skin.style, out.paths);
    markStage(out.paths, stage_start, number, 1);
    stage_start = out.paths.size();
    appendFill(roof_fill, p.roofing, p, out);
    markStage(out.paths, stage_start, number, 2);
    const std::optional<SkinFillParams> bridge = p.bridge ? p.bridge(part) : std::nullopt;
    const std::size_t before = out.paths.size();
    appendFill(skin_fill, bridge ? *bridge : p.skin, p, out);
    for (std::size_t i = before; bridge && i < out.paths.size(); ++i) {
        out.paths[i].bridge = true;
        out.paths[i].fan_ratio = bridge->bridge_fan_ratio.value_or(-1);
    }
    markStage(out.paths, before, number, 3);
    stage_start = out.paths.size();
    appendGapLines(out.gaps, p, out.paths);
    markStage(out.paths, stage_start, number, 4);
    out.gaps.clear();
}

}  // namespace

std::vector<ExtrusionPath> generateSkinPaths(const Paths& skin_area, const Paths& roofing_area,
                                             const SkinPathParams& params) {
    std::vector<ExtrusionPath> paths;
    if (skin_area.empty() || params.skin.style.width_um <= 0)
        return paths;
    SkinOutput out{paths, {}, 0, 0};
    for (const Paths& part : splitIslands(skin_area))
        appendSkinPart(part, roofing_area, params, out);
    return paths;
}

std::vector<ExtrusionPath> perimeterGapLines(const Paths& gaps, const SkinPathParams& params) {
    std::vector<ExtrusionPath> lines;
    appendGapLines(gaps, params, lines);
    for (ExtrusionPath& line : lines)
        line.mergeable = true;
    return lines;
}

}  // namespace mixengine
