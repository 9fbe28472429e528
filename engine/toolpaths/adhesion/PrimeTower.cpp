#include "toolpaths/adhesion/PrimeTower.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/Angles.h"
#include "geometry/Clip.h"
#include "geometry/PolygonOps.h"
#include "toolpaths/core/FeatureStyle.h"
#include "toolpaths/support/Support.h"

namespace mixengine {
namespace {

constexpr int kCircleSegments = 32;

FeatureStyle towerStyle(const TowerInput& in, int extruder, int layer) {
    const Settings& s = trainSettings(*in.global, in.extruders, extruder);
    FeatureStyle style = featureStyle(
        s, {key::prime_tower_line_width, key::speed_prime_tower, key::prime_tower_flow, {}}, layer);
    style.extruder = extruder;
    return style;
}

int adhesionExtruder(const Settings& g) {
    return std::max(0, g.extruderIndex(key::adhesion_extruder_nr));
}

bool towerBrimEnabled(const Settings& g) {
    return g.boolean(key::prime_tower_brim_enable) && g.text(key::adhesion_type) != "raft";
}

/// The width of the tower's own brim (0 without it).
coord_um towerBrimWidth(const Settings& g, const std::vector<Settings>* extruders) {
    if (!towerBrimEnabled(g))
        return 0;
    const Settings& a = trainSettings(g, extruders, adhesionExtruder(g));
    return std::llround(double(a.integer(key::brim_line_count)) *
                        double(a.lengthMicrons(key::skirt_brim_line_width)) *
                        a.ratio(key::initial_layer_line_width_factor));
}

/// Every extruder of the machine, lowest material_adhesion_tendency first (ties by number).
std::vector<int> towerOrder(const Settings& g, const std::vector<Settings>* extruders) {
    const std::size_t count = extruders && !extruders->empty() ? extruders->size() : 1;
    std::vector<int> order(count);
    std::vector<double> tendency(count, 0.0);
    for (std::size_t e = 0; e < count; ++e) {
        order[e] = static_cast<int>(e);
        const Settings& s = trainSettings(g, extruders, static_cast<int>(e));
        tendency[e] = s.real(key::material_adhesion_tendency);
    }
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
        return tendency[static_cast<std::size_t>(a)] < tendency[static_cast<std::size_t>(b)];
    });
    return order;
}

/// One extruder's rings, `inset_um` inside the outline and inwards until they hold `volume_mm3`
/// (each mm of ring holding `mm3_per_mm`); `rings` is set to how many were made.
Paths ringsOf(const Path& outline, coord_um inset_um, coord_um width_um, double mm3_per_mm, double volume_mm3,
              int& rings) {
    Paths loops;
    double volume = 0;
    for (rings = 0; volume < volume_mm3; ++rings) {
        const Paths ring = offsetMiter({outline}, -(inset_um + rings * width_um + width_um / 2));
        if (ring.empty())
            break;
        for (const Path& loop : ring) {
            loops.push_back(loop);
            volume += lengthUm(loop, true) / 1000.0 * mm3_per_mm;
        }
    }
    return loops;
}

/// Concentric loops of `width_um` filling the whole outline (the first layer's tower).
Paths filledDisc(const Path& outline, coord_um width_um) {
    Paths loops;
    for (Paths ring = offsetMiter({outline}, -width_um / 2); !ring.empty();
         ring = offsetMiter(ring, -width_um, Loops::United))
        loops.insert(loops.end(), ring.begin(), ring.end());
    return loops;
}

/// Brim lines around the tower: brim_line_count, more while shorter than skirt_brim_minimal_length.
std::vector<ExtrusionPath> towerBrim(const TowerInput& in, const Path& outline) {
    const Settings& g = *in.global;
    const int nr = adhesionExtruder(g);
    const Settings& a = trainSettings(g, in.extruders, nr);
    FeatureStyle style = featureStyle(
        a, {key::skirt_brim_line_width, key::skirt_brim_speed, key::skirt_brim_material_flow, {}}, 0);
    style.speed_mm_s = a.velocityMmPerS(key::skirt_brim_speed);
    style.extruder = nr;
    const long long count = a.integer(key::brim_line_count);
    const double min_length_um = a.millimetres(key::skirt_brim_minimal_length) * 1000.0;
    constexpr long long kMaxExtra = 1000;
    std::vector<ExtrusionPath> lines;
    double total_um = 0;
    for (long long i = 0; i < count || (total_um < min_length_um && i < count + kMaxExtra); ++i) {
        for (const Path& loop : offsetPolygons({outline}, style.width_um / 2 + i * style.width_um)) {
            lines.push_back(styledPath(loop, true, Feature::Skirt, style));
            total_um += lengthUm(loop, true);
        }
    }
    std::reverse(lines.begin(), lines.end());  // outermost first, as the skirt and brim
    return lines;
}

/// The rings of every extruder on one layer (layer 0: the outermost extruder's filled disc).
std::vector<ExtrusionPath> towerLayer(const TowerInput& in, const std::vector<std::pair<int, Paths>>& rings,
                                      const Path& outline, int layer) {
    std::vector<ExtrusionPath> paths;
    if (layer == 0) {
        const int outermost = rings.front().first;
        const FeatureStyle style = towerStyle(in, outermost, 0);
        appendStyledLoops(filledDisc(outline, style.width_um), Feature::PrimeTower, style, paths);
        return paths;
    }
    for (const auto& [extruder, loops] : rings)
        appendStyledLoops(loops, Feature::PrimeTower, towerStyle(in, extruder, layer), paths);
    return paths;
}

}  // namespace

int lastMultiExtruderLayer(const std::vector<std::set<int>>& used) {
    for (std::size_t i = used.size(); i-- > 0;) {
        if (used[i].size() >= 2)
            return static_cast<int>(i);
    }
    return -1;
}

Path primeTowerOutline(const Settings& g, const std::vector<Settings>* extruders) {
    if (!g.boolean(key::prime_tower_enable))
        return {};
    const coord_um size = g.lengthMicrons(key::prime_tower_size);
    if (size <= 10 || g.real(key::prime_tower_min_volume) * 1000.0 <= 10)  // CuraEngine compares them in µm
        return {};
    const coord_um brim = towerBrimWidth(g, extruders);
    const double r = double(size) / 2;
    const double cx = double(g.lengthMicrons(key::prime_tower_position_x) - brim) - r;
    const double cy = double(g.lengthMicrons(key::prime_tower_position_y) - brim) + r;
    Path circle;
    for (int i = 0; i < kCircleSegments; ++i) {
        const double a = 2 * std::numbers::pi * i / kCircleSegments;
        circle.push_back({std::llround(cx + r * std::cos(a)), std::llround(cy + r * std::sin(a))});
    }
    return circle;
}

PrimeTowerResult generatePrimeTower(const TowerInput& in) {
    PrimeTowerResult out;
    out.layers.resize(in.heights->size());
    const Path outline = primeTowerOutline(*in.global, in.extruders);
    const int last = lastMultiExtruderLayer(in.used);
    if (outline.empty() || last < 0)
        return out;
    // As CuraEngine: the rings are sized once, for layer_height, each extruder inside the ones before.
    const double thickness_mm = micronsToMm(in.global->lengthMicrons(key::layer_height));
    std::vector<std::pair<int, Paths>> rings;
    coord_um inset = 0;
    for (int extruder : towerOrder(*in.global, in.extruders)) {
        const Settings& s = trainSettings(*in.global, in.extruders, extruder);
        const FeatureStyle style = towerStyle(in, extruder, 1);
        int made = 0;
        rings.emplace_back(extruder, ringsOf(outline, inset, style.width_um,
                                             micronsToMm(style.width_um) * thickness_mm * style.flow,
                                             s.real(key::prime_tower_min_volume), made));
        inset += made * style.width_um;
    }
    const int top = std::min(last + 1, static_cast<int>(out.layers.size()) - 1);
    for (int layer = 0; layer <= top; ++layer)
        out.layers[static_cast<std::size_t>(layer)] = towerLayer(in, rings, outline, layer);
    if (towerBrimEnabled(*in.global))
        out.brim = towerBrim(in, outline);
    out.outermost = rings.front().first;
    out.last_forced_layer = last;
    const double r = double(in.global->lengthMicrons(key::prime_tower_size)) / 2;
    out.middle = {std::llround(double(outline.front().X) - r), outline.front().Y};  // vertex 0 is at angle 0
    return out;
}

std::vector<std::vector<ExtrusionPath>> generateOozeShield(const TowerInput& in) {
    std::vector<std::vector<ExtrusionPath>> layers(in.heights->size());
    const Settings& g = *in.global;
    const int last = lastMultiExtruderLayer(in.used);
    if (!g.boolean(key::ooze_shield_enabled) || last < 0)
        return layers;
    const coord_um dist = g.lengthMicrons(key::ooze_shield_dist);
    std::vector<Paths> shield(static_cast<std::size_t>(last) + 1);
    for (std::size_t i = 0; i < shield.size(); ++i)
        shield[i] = offsetPolygons((*in.model)[i], dist);
    const double angle = g.angleDegrees(key::ooze_shield_angle);
    if (angle <= 89) {
        const coord_um slope =
            std::llround(std::tan(radiansFromDegrees(angle)) * double(g.lengthMicrons(key::layer_height)));
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
        FeatureStyle style = featureStyle(
            s, {key::skirt_brim_line_width, key::skirt_brim_speed, key::skirt_brim_material_flow, {}},
            static_cast<int>(i));
        style.speed_mm_s = s.velocityMmPerS(key::skirt_brim_speed);  // shields are not slowed down either
        style.extruder = extruder;
        for (const Path& p : unionOf(shield[i])) {
            if (counterClockwise(p))
                layers[i].push_back(styledPath(p, true, Feature::Skirt, style));
        }
    }
    return layers;
}

}  // namespace mixengine
