#include "toolpaths/core/FeatureStyle.h"

#include <cmath>

namespace mixengine {

int ownExtruder(const Settings& s) {
    // extruder_nr is an extruder train's setting (fdmextruder): the global scope has none, and prints with 0
    if (!s.has(key::extruder_nr))
        return 0;
    const int nr = s.extruderIndex(key::extruder_nr);
    return nr < 0 ? 0 : nr;
}

double slowdownBlend(const Settings& s, double value, double first, int layer) {
    if (layer < 0)
        return value;
    const long long slowdown = s.integer(key::speed_slowdown_layers);
    if (layer >= slowdown)
        return value;  // speed_slowdown_layers 0: no slow first layer either, as in CuraEngine 4.13
    const double t = double(layer) / double(slowdown);
    return first + (value - first) * t;
}

double layerSpeed(const Settings& s, Key<SettingUnit::MmPerS> speed_key, int layer) {
    return slowdownValue(s, speed_key, key::speed_print_layer_0, layer);
}

FeatureStyle featureStyle(const Settings& s, const FeatureKeys& keys, int layer) {
    FeatureStyle style;
    style.width_um = s.lengthMicrons(keys.width);
    if (layer == 0)
        style.width_um = static_cast<coord_um>(
            std::llround(double(style.width_um) * s.ratio(key::initial_layer_line_width_factor)));
    style.speed_mm_s = layerSpeed(s, keys.speed, layer);
    style.flow = s.ratio(keys.flow);
    if (layer == 0)
        style.flow *= s.ratio(key::material_flow_layer_0);
    const int nr = keys.extruder ? s.extruderIndex(*keys.extruder) : -1;
    style.extruder = nr >= 0 ? nr : ownExtruder(s);
    return style;
}

MeshStyles meshStyles(const Settings& s, int layer) {
    MeshStyles m;
    m.wall_0 = featureStyle(
        s, {key::wall_line_width_0, key::speed_wall_0, key::wall_0_material_flow, key::wall_0_extruder_nr},
        layer);
    m.wall_x = featureStyle(
        s, {key::wall_line_width_x, key::speed_wall_x, key::wall_x_material_flow, key::wall_x_extruder_nr},
        layer);
    m.skin = featureStyle(
        s, {key::skin_line_width, key::speed_topbottom, key::skin_material_flow, key::top_bottom_extruder_nr},
        layer);
    m.roofing = featureStyle(
        s,
        {key::roofing_line_width, key::speed_roofing, key::roofing_material_flow, key::roofing_extruder_nr},
        layer);
    m.infill = featureStyle(
        s, {key::infill_line_width, key::speed_infill, key::infill_material_flow, key::infill_extruder_nr},
        layer);
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
