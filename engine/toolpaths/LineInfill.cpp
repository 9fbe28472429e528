#include "toolpaths/LineInfill.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mixengine {
namespace {

Point2 rotate(const Point2& p, double cos_a, double sin_a) {
    return {static_cast<coord_um>(std::llround(p.X * cos_a - p.Y * sin_a)),
            static_cast<coord_um>(std::llround(p.X * sin_a + p.Y * cos_a))};
}

}  // namespace

std::vector<ExtrusionPath> generateLineInfill(const Paths& area, const LineInfillParams& params) {
    std::vector<ExtrusionPath> lines;
    if (params.line_distance_um <= 0 || area.empty())
        return lines;
    const double angle = params.angle_degrees * std::numbers::pi / 180.0;
    const double cos_a = std::cos(angle), sin_a = std::sin(angle);

    // Work in a frame where the lines are vertical: rotate the area by -angle.
    Paths rotated = area;
    for (Path& path : rotated)
        for (Point2& p : path)
            p = rotate(p, cos_a, -sin_a);
    ClipperLib::Clipper bounds;
    bounds.AddPaths(rotated, ClipperLib::ptSubject, true);
    const ClipperLib::IntRect box = bounds.GetBounds();
    const coord_um step = params.line_distance_um;
    const coord_um first = (box.left / step) * step;
    Paths scan;
    for (coord_um x = first; x <= box.right; x += step)
        scan.push_back({{x, box.bottom + 10}, {x, box.top - 10}});

    ClipperLib::Clipper clipper;
    clipper.AddPaths(scan, ClipperLib::ptSubject, false);
    clipper.AddPaths(rotated, ClipperLib::ptClip, true);
    ClipperLib::PolyTree tree;
    clipper.Execute(ClipperLib::ctIntersection, tree, ClipperLib::pftEvenOdd, ClipperLib::pftEvenOdd);
    Paths clipped;
    ClipperLib::OpenPathsFromPolyTree(tree, clipped);

    // Sort along the scan direction so consecutive lines are neighbours, then zig-zag.
    for (Path& line : clipped) {
        if (line.size() != 2)
            continue;
        if (line[0].Y > line[1].Y)
            std::swap(line[0], line[1]);
    }
    std::sort(clipped.begin(), clipped.end(), [](const Path& a, const Path& b) {
        return a.front().X != b.front().X ? a.front().X < b.front().X : a.front().Y < b.front().Y;
    });
    bool reverse = false;
    for (Path& line : clipped) {
        if (line.size() != 2)
            continue;
        if (reverse)
            std::swap(line[0], line[1]);
        reverse = !reverse;
        ExtrusionPath path;
        for (const Point2& p : line)
            path.points.push_back(rotate(p, cos_a, sin_a));
        path.width_um = params.line_width_um;
        path.feature = params.feature;
        path.speed_mm_s = params.speed_mm_s;
        lines.push_back(std::move(path));
    }
    return lines;
}

}  // namespace mixengine
