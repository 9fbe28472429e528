#include "toolpaths/core/FeatureStyle.h"

#include <cmath>

namespace mixengine {

int ownExtruder(const Settings& s) {
    if (!s.has("extruder_nr"))
        return 0;
    const int nr = s.extruderIndex("extruder_nr");
    return nr < 0 ? 0 : nr;
}

double slowdownValue(const Settings& s, std::string_view key, std::string_view first_key, int layer) {
    const double value = s.real(key);
    if (!s.has(first_key) || layer < 0)
        return value;
    const long long slowdown = s.has("speed_slowdown_layers") ? s.integer("speed_slowdown_layers") : 0;
    if (layer >= slowdown)
        return value;  // speed_slowdown_layers 0: no slow first layer either, as in CuraEngine 4.13
    const double first = s.real(first_key);
    const double t = double(layer) / double(slowdown);
    return first + (value - first) * t;
}

double layerSpeed(const Settings& s, std::string_view speed_key, int layer) {
    return slowdownValue(s, speed_key, "speed_print_layer_0", layer);
}

FeatureStyle featureStyle(const Settings& s, const FeatureKeys& keys, int layer) {
    FeatureStyle style;
    style.width_um = s.lengthMicrons(keys.width);
    if (layer == 0 && s.has("initial_layer_line_width_factor"))
        style.width_um = static_cast<coord_um>(
            std::llround(double(style.width_um) * s.ratio("initial_layer_line_width_factor")));
    style.speed_mm_s = layerSpeed(s, keys.speed, layer);
    style.flow = s.has(keys.flow) ? s.ratio(keys.flow) : 1.0;
    if (layer == 0 && s.has("material_flow_layer_0"))
        style.flow *= s.ratio("material_flow_layer_0");
    const int nr = s.has(keys.extruder) ? s.extruderIndex(keys.extruder) : -1;
    style.extruder = nr >= 0 ? nr : ownExtruder(s);
    return style;
}

MeshStyles meshStyles(const Settings& s, int layer) {
    MeshStyles m;
    m.wall_0 = featureStyle(
        s, {"wall_line_width_0", "speed_wall_0", "wall_0_material_flow", "wall_0_extruder_nr"}, layer);
    m.wall_x = featureStyle(
        s, {"wall_line_width_x", "speed_wall_x", "wall_x_material_flow", "wall_x_extruder_nr"}, layer);
    m.skin = featureStyle(
        s, {"skin_line_width", "speed_topbottom", "skin_material_flow", "top_bottom_extruder_nr"}, layer);
    m.roofing =
        s.has("roofing_line_width") && s.has("speed_roofing")
            ? featureStyle(
                  s, {"roofing_line_width", "speed_roofing", "roofing_material_flow", "roofing_extruder_nr"},
                  layer)
            : m.skin;
    m.infill = featureStyle(
        s, {"infill_line_width", "speed_infill", "infill_material_flow", "infill_extruder_nr"}, layer);
    return m;
}

ExtrusionPath styledPath(const Path& points, bool closed, Feature feature, const FeatureStyle& style) {
    ExtrusionPath path;
    path.points = points;
    path.closed = closed;
    path.width_um = style.width_um;
    path.feature = feature;
    path.speed_mm_s = style.speed_mm_s;
    path.flow = style.flow;
    path.extruder = style.extruder;
    return path;
}

void appendStyledLoops(const Paths& loops, Feature feature, const FeatureStyle& style,
                       std::vector<ExtrusionPath>& out) {
    for (const Path& loop : loops) {
        if (loop.size() >= 3)
            out.push_back(styledPath(loop, true, feature, style));
    }
}

}  // namespace mixengine
