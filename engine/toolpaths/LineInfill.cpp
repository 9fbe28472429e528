#include "toolpaths/LineInfill.h"

#include <algorithm>

#include "toolpaths/LineFrame.h"
#include "toolpaths/PolygonOps.h"

namespace mixengine {
namespace {

/// The vertical lines x = shift + k·step across `box`, each only as long as the edges of `area`
/// that reach its x (10 µm more at both ends), so that Clipper sweeps fewer of them at a time; a
/// line no edge reaches is left out (it cannot meet the area). The pieces inside are the same but
/// for Clipper's rounding of their ends (1 µm at most).
Paths scanLines(const Paths& area, const ClipperLib::IntRect& box, coord_um step, coord_um shift) {
    const coord_um first = floorDiv(box.left - shift, step) * step + shift;
    const coord_um start = first < box.left ? first + step : first;
    if (start > box.right)
        return {};
    const std::size_t count = static_cast<std::size_t>((box.right - start) / step) + 1;
    std::vector<coord_um> low(count, box.bottom + 1), high(count, box.top - 1);
    for (const Path& loop : area) {
        for (std::size_t i = 0; i < loop.size(); ++i) {
            const Point2& a = loop[i];
            const Point2& b = loop[(i + 1) % loop.size()];
            const coord_um x0 = std::min(a.X, b.X), x1 = std::max(a.X, b.X);
            if (x1 < start)
                continue;
            const coord_um y0 = std::min(a.Y, b.Y), y1 = std::max(a.Y, b.Y);
            const coord_um k0 = x0 <= start ? 0 : (x0 - start + step - 1) / step;
            for (coord_um k = k0; k < coord_um(count) && start + k * step <= x1; ++k) {
                low[std::size_t(k)] = std::min(low[std::size_t(k)], y0);
                high[std::size_t(k)] = std::max(high[std::size_t(k)], y1);
            }
        }
    }
    Paths scan;
    for (std::size_t k = 0; k < count; ++k) {
        const coord_um x = start + coord_um(k) * step;
        if (low[k] <= high[k])
            scan.push_back({{x, low[k] - 10}, {x, high[k] + 10}});
    }
    return scan;
}

}  // namespace

Paths lineSegments(const Paths& area, coord_um line_distance_um, double angle_degrees, coord_um shift_um) {
    if (line_distance_um <= 0 || area.empty())
        return {};
    const LineFrame frame(angle_degrees);  // the lines are vertical in it
    const Paths rotated = frame.into(area);
    const ClipperLib::IntRect box = boundsOf(rotated);
    const coord_um shift = linePhase(shift_um, line_distance_um);
    Paths clipped = clipLines(scanLines(rotated, box, line_distance_um, shift), rotated);
    for (Path& line : clipped) {
        if (line.size() != 2)
            continue;
        if (line[0].Y > line[1].Y)
            std::swap(line[0], line[1]);
    }
    std::erase_if(clipped, [](const Path& line) { return line.size() != 2 || line[0] == line[1]; });
    std::sort(clipped.begin(), clipped.end(), [](const Path& a, const Path& b) {
        return a.front().X != b.front().X ? a.front().X < b.front().X : a.front().Y < b.front().Y;
    });
    bool reverse = false;
    for (Path& line : clipped) {
        if (reverse)
            std::swap(line[0], line[1]);
        reverse = !reverse;
    }
    frame.back(clipped);
    return clipped;
}

std::vector<ExtrusionPath> generateLineInfill(const Paths& area, const LineInfillParams& params) {
    std::vector<ExtrusionPath> lines;
    for (Path& segment : lineSegments(area, params.line_distance_um, params.angle_degrees, params.shift_um)) {
        ExtrusionPath path;
        path.points = std::move(segment);
        path.width_um = params.line_width_um;
        path.feature = params.feature;
        path.speed_mm_s = params.speed_mm_s;
        path.flow = params.flow;
        path.extruder = params.extruder;
        lines.push_back(std::move(path));
    }
    return lines;
}

}  // namespace mixengine
