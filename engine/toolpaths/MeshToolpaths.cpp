#include "toolpaths/MeshToolpaths.h"

#include "common/ParallelFor.h"
#include "toolpaths/LineInfill.h"
#include "toolpaths/Skin.h"
#include "toolpaths/Walls.h"

namespace mixengine {
namespace {

struct SpeedSet {
    double wall_outer, wall_inner, skin, infill;
};

SpeedSet speedsFor(const Settings& s, int layer) {
    if (layer == 0) {
        const double v = s.velocityMmPerS("speed_print_layer_0");
        return {v, v, v, v};
    }
    return {s.velocityMmPerS("speed_wall_0"), s.velocityMmPerS("speed_wall_x"),
            s.velocityMmPerS("speed_topbottom"), s.velocityMmPerS("speed_infill")};
}

WallParams wallParams(const Settings& s, const SpeedSet& speed) {
    WallParams p;
    p.wall_count = static_cast<int>(s.integer("wall_line_count"));
    p.outer_width_um = s.lengthMicrons("wall_line_width_0");
    p.inner_width_um = s.lengthMicrons("wall_line_width_x");
    p.outer_inset_um = s.lengthMicrons("wall_0_inset");
    p.outer_speed_mm_s = speed.wall_outer;
    p.inner_speed_mm_s = speed.wall_inner;
    return p;
}

void appendInfill(const Paths& area, const Settings& s, int layer, double speed,
                  std::vector<ExtrusionPath>& out) {
    LineInfillParams p;
    p.line_distance_um = s.lengthMicrons("infill_line_distance");
    p.line_width_um = s.lengthMicrons("infill_line_width");
    p.speed_mm_s = speed;
    const std::string pattern = s.has("infill_pattern") ? s.text("infill_pattern") : "lines";
    if (pattern == "lines" || pattern == "zigzag") {
        p.angle_degrees = layer % 2 == 0 ? 45 : 135;
        out = generateLineInfill(area, p);
        return;
    }
    // Grid and every pattern not implemented yet: two crossing line sets.
    p.line_distance_um *= 2;
    out = generateLineInfill(area, p);
    p.angle_degrees = 135;
    auto cross = generateLineInfill(area, p);
    out.insert(out.end(), cross.begin(), cross.end());
}

}  // namespace

std::vector<MeshLayerGroups> generateMeshToolpaths(const std::vector<SlicedLayer>& layers,
                                                   const Settings& settings, int threads) {
    std::vector<MeshLayerGroups> result(layers.size());
    std::vector<Paths> inner_areas(layers.size());
    parallelFor(layers.size(), threads, [&](std::size_t i) {
        const SpeedSet speed = speedsFor(settings, static_cast<int>(i));
        WallResult walls = generateWalls(layers[i].outlines, wallParams(settings, speed));
        for (ExtrusionPath& path : walls.walls) {
            (path.feature == Feature::WallOuter ? result[i].outer_walls : result[i].inner_walls)
                .push_back(std::move(path));
        }
        inner_areas[i] = std::move(walls.inner_area);
    });

    const int top = static_cast<int>(settings.integer("top_layers"));
    const int bottom = static_cast<int>(settings.integer("bottom_layers"));
    const std::vector<Paths> skins = computeSkinAreas(inner_areas, top, bottom, threads);

    parallelFor(layers.size(), threads, [&](std::size_t i) {
        const int layer = static_cast<int>(i);
        const SpeedSet speed = speedsFor(settings, layer);
        LineInfillParams skin;
        skin.line_width_um = settings.lengthMicrons("skin_line_width");
        skin.line_distance_um = skin.line_width_um;
        skin.angle_degrees = layer % 2 == 0 ? 45 : 135;
        skin.feature = Feature::Skin;
        skin.speed_mm_s = speed.skin;
        result[i].skin = generateLineInfill(skins[i], skin);
        const Paths sparse = differenceOf(inner_areas[i], skins[i]);
        appendInfill(sparse, settings, layer, speed.infill, result[i].infill);
    });
    return result;
}

}  // namespace mixengine
