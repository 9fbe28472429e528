#include "toolpaths/PrimeTower.h"

#include <cmath>
#include <numbers>

#include "geometry/Angles.h"
#include "toolpaths/FeatureStyle.h"
#include "toolpaths/PolygonOps.h"
#include "toolpaths/Support.h"

namespace mixengine {
namespace {

constexpr int kCircleSegments = 32;

FeatureStyle towerStyle(const TowerInput& in, int extruder, int layer) {
    const Settings& s = trainSettings(*in.global, in.extruders, extruder);
    FeatureStyle style =
        featureStyle(s, {"prime_tower_line_width", "speed_prime_tower", "prime_tower_flow", ""}, layer);
    style.extruder = extruder;
    return style;
}

/// One extruder's rings from `outer` inwards until they hold `volume_mm3`; returns the area left.
Paths addRings(Paths area, const FeatureStyle& style, double volume_mm3, coord_um thickness, bool fill,
               std::vector<ExtrusionPath>& out) {
    double volume = 0;
    while (!area.empty() && (fill || volume < volume_mm3)) {
        const Paths ring = offsetMiter(area, -style.width_um / 2);
        for (const Path& loop : ring) {
            out.push_back(styledPath(loop, true, Feature::PrimeTower, style));
            volume += lengthUm(loop, true) * double(style.width_um) * double(thickness) * style.flow * 1e-9;
        }
        area = ring.empty() ? Paths{} : offsetMiter(ring, -style.width_um / 2);
    }
    return area;
}

}  // namespace

int lastMultiExtruderLayer(const std::vector<std::set<int>>& used) {
    for (std::size_t i = used.size(); i-- > 0;) {
        if (used[i].size() >= 2)
            return static_cast<int>(i);
    }
    return -1;
}

Path primeTowerOutline(const Settings& g) {
    if (!g.has("prime_tower_enable") || !g.boolean("prime_tower_enable"))
        return {};
    const coord_um size = g.lengthMicrons("prime_tower_size");
    const double r = double(size) / 2;
    const double cx = double(g.lengthMicrons("prime_tower_position_x")) - r;
    const double cy = double(g.lengthMicrons("prime_tower_position_y")) + r;
    Path circle;
    for (int i = 0; i < kCircleSegments; ++i) {
        const double a = 2 * std::numbers::pi * i / kCircleSegments;
        circle.push_back({std::llround(cx + r * std::cos(a)), std::llround(cy + r * std::sin(a))});
    }
    return circle;
}

std::vector<std::vector<ExtrusionPath>> generatePrimeTower(const TowerInput& in) {
    std::vector<std::vector<ExtrusionPath>> layers(in.heights->size());
    const Path outline = primeTowerOutline(*in.global);
    const int last = lastMultiExtruderLayer(in.used);
    if (outline.empty() || last < 0)
        return layers;
    // As CuraEngine: the rings are sized once, for layer_height; on layer 0 the first extruder
    // fills the whole disc and the others print nothing there.
    const coord_um thickness = in.global->lengthMicrons("layer_height");
    for (int layer = 0; layer <= last; ++layer) {
        const std::size_t i = static_cast<std::size_t>(layer);
        Paths area{outline};
        for (int extruder : in.used[i]) {
            const Settings& s = trainSettings(*in.global, in.extruders, extruder);
            const double volume = s.has("prime_tower_min_volume") ? s.real("prime_tower_min_volume") : 0.0;
            area = addRings(area, towerStyle(in, extruder, layer), volume, thickness, layer == 0, layers[i]);
            if (layer == 0)
                break;
        }
    }
    return layers;
}

std::vector<std::vector<ExtrusionPath>> generateOozeShield(const TowerInput& in) {
    std::vector<std::vector<ExtrusionPath>> layers(in.heights->size());
    const Settings& g = *in.global;
    const int last = lastMultiExtruderLayer(in.used);
    if (!g.has("ooze_shield_enabled") || !g.boolean("ooze_shield_enabled") || last < 0)
        return layers;
    const coord_um dist = g.lengthMicrons("ooze_shield_dist");
    std::vector<Paths> shield(static_cast<std::size_t>(last) + 1);
    for (std::size_t i = 0; i < shield.size(); ++i)
        shield[i] = offsetPolygons((*in.model)[i], dist);
    const double angle = g.angleDegrees("ooze_shield_angle");
    if (angle <= 89) {
        const coord_um slope =
            std::llround(std::tan(radiansFromDegrees(angle)) * double(g.lengthMicrons("layer_height")));
        for (std::size_t i = 1; i < shield.size(); ++i)
            shield[i] = unionOf(shield[i], offsetPolygons(shield[i - 1], -slope));
        for (std::size_t i = shield.size(); i-- > 1;)
            shield[i - 1] = unionOf(shield[i - 1], offsetPolygons(shield[i], -slope));
    }
    for (std::size_t i = 0; i < shield.size(); ++i) {
        if (in.used[i].empty())
            continue;
        const int extruder = *in.used[i].begin();
        const Settings& s = trainSettings(g, in.extruders, extruder);
        FeatureStyle style =
            featureStyle(s, {"skirt_brim_line_width", "skirt_brim_speed", "skirt_brim_material_flow", ""},
                         static_cast<int>(i));
        style.speed_mm_s = s.velocityMmPerS("skirt_brim_speed");  // shields are not slowed down either
        style.extruder = extruder;
        for (const Path& p : unionOf(shield[i])) {
            if (ClipperLib::Orientation(p))
                layers[i].push_back(styledPath(p, true, Feature::Skirt, style));
        }
    }
    return layers;
}

}  // namespace mixengine
