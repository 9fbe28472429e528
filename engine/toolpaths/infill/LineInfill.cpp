#include "toolpaths/infill/LineInfill.h"

#include <algorithm>

#include "toolpaths/infill/LineFrame.h"
#include "toolpaths/infill/ScanCrossings.h"

namespace mixengine {

Paths lineSegments(const Paths& area, coord_um line_distance_um, double angle_degrees, coord_um shift_um) {
    if (line_distance_um <= 0 || area.empty())
        return {};
    const LineFrame frame(angle_degrees);  // the lines are vertical in it
    const std::vector<ScanCrossing> crossings =
        findScanCrossings(frame.into(area), line_distance_um, linePhase(shift_um, line_distance_um));
    const std::vector<long> partner = pairOnScanlines(crossings);
    Paths clipped;  // the pieces of the scanlines inside the area: its crossings paired even-odd
    for (std::size_t i = 0; i < crossings.size(); ++i) {
        if (partner[i] > static_cast<long>(i))
            clipped.push_back({crossings[i].point, crossings[std::size_t(partner[i])].point});
    }
    for (Path& line : clipped) {
        if (line[0].Y > line[1].Y)
            std::swap(line[0], line[1]);
    }
    std::erase_if(clipped, [](const Path& line) { return line[0] == line[1]; });
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
