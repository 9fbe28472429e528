#include "toolpaths/Walls.h"

namespace mixengine {

Paths offsetPolygons(const Paths& polygons, coord_um delta_um) {
    ClipperLib::ClipperOffset offset(2.0, 10.0);  // arc tolerance 10 µm
    offset.AddPaths(polygons, ClipperLib::jtRound, ClipperLib::etClosedPolygon);
    Paths result;
    offset.Execute(result, static_cast<double>(delta_um));
    return result;
}

namespace {

void appendLoops(const Paths& loops, coord_um width, Feature feature, double speed,
                 std::vector<ExtrusionPath>& out) {
    for (const Path& loop : loops) {
        if (loop.size() < 3)
            continue;
        ExtrusionPath path;
        path.points = loop;
        path.closed = true;
        path.width_um = width;
        path.feature = feature;
        path.speed_mm_s = speed;
        out.push_back(std::move(path));
    }
}

}  // namespace

WallResult generateWalls(const Paths& outlines, const WallParams& params) {
    WallResult result;
    if (params.wall_count <= 0) {
        result.inner_area = outlines;
        return result;
    }
    Paths centre = offsetPolygons(outlines, -(params.outer_width_um / 2 + params.outer_inset_um));
    appendLoops(centre, params.outer_width_um, Feature::WallOuter, params.outer_speed_mm_s, result.walls);
    coord_um previous_half = params.outer_width_um / 2;
    for (int i = 1; i < params.wall_count && !centre.empty(); ++i) {
        centre = offsetPolygons(centre, -(previous_half + params.inner_width_um / 2));
        appendLoops(centre, params.inner_width_um, Feature::WallInner, params.inner_speed_mm_s, result.walls);
        previous_half = params.inner_width_um / 2;
    }
    result.inner_area = centre.empty() ? Paths{} : offsetPolygons(centre, -previous_half);
    return result;
}

}  // namespace mixengine
