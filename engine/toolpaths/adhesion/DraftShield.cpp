#include "toolpaths/adhesion/DraftShield.h"

#include <algorithm>
#include <limits>

#include "geometry/Clip.h"
#include "geometry/PolygonOps.h"
#include "slicing/OutlineCleanup.h"
#include "toolpaths/adhesion/Adhesion.h"
#include "toolpaths/core/FeatureStyle.h"
#include "toolpaths/support/Support.h"

namespace mixengine {
namespace {

constexpr coord_um kHullOvershootUm = 100'000;  // as CuraEngine

/// The number of layers the shield covers (from the first printed one), and whether it is limited.
std::size_t shieldLayers(const Settings& g, std::size_t printed) {
    if (g.text(key::draft_shield_height_limitation) != "limited")
        return printed;
    const coord_um height = std::max<coord_um>(1, g.lengthMicrons(key::layer_height));
    const coord_um above = g.lengthMicrons(key::draft_shield_height) - g.lengthMicrons(key::layer_height_0);
    return static_cast<std::size_t>(std::max<coord_um>(0, above / height + 1));
}

/// The models' outlines on the sampled layers, united, and the convex hull of the support's lines
/// there (many small loops: their hull gives the same approximate hull far faster).
Paths sampledOutlines(const DraftShieldInput& in, std::size_t layers) {
    const coord_um height = std::max<coord_um>(1, in.global->lengthMicrons(key::layer_height));
    const std::size_t skip = static_cast<std::size_t>(500 / height + 1);
    Paths models, support;
    for (std::size_t k = 0; k < layers; k += skip) {
        const std::size_t i = in.first_layer + k;
        const Paths& model = (*in.model)[i];
        models.insert(models.end(), model.begin(), model.end());
        if (in.support != nullptr && i < in.support->size()) {
            for (const ExtrusionPath& path : (*in.support)[i])
                support.push_back(path.points);
        }
    }
    Paths all = unionOf(models);
    if (!support.empty())
        all.push_back(convexHull(support));
    return all;
}

/// The shield simplified as CuraEngine 4.13 simplifies it (every extruder prints it): with the largest
/// meshfix_maximum_resolution and the smallest meshfix_maximum_deviation of the extruders.
Paths simplifiedForEveryExtruder(Paths shield, const Settings& g, const std::vector<Settings>* extruders) {
    coord_um resolution = g.lengthMicrons(key::meshfix_maximum_resolution);
    coord_um deviation = g.lengthMicrons(key::meshfix_maximum_deviation);
    if (extruders != nullptr && !extruders->empty()) {
        resolution = 0;
        deviation = std::numeric_limits<coord_um>::max();
        for (const Settings& e : *extruders) {
            resolution = std::max(resolution, e.lengthMicrons(key::meshfix_maximum_resolution));
            deviation = std::min(deviation, e.lengthMicrons(key::meshfix_maximum_deviation));
        }
    }
    for (Path& loop : shield)
        loop = simplifyLoop(loop, resolution, deviation);
    std::erase_if(shield, [](const Path& loop) { return loop.size() < 3; });
    return shield;
}

FeatureStyle shieldStyle(const DraftShieldInput& in, int layer) {
    const Settings& s = trainSettings(*in.global, in.extruders, 0);
    FeatureStyle style = featureStyle(
        s, {key::skirt_brim_line_width, key::skirt_brim_speed, key::skirt_brim_material_flow, {}}, layer);
    style.speed_mm_s = s.velocityMmPerS(key::skirt_brim_speed);  // as the skirt: not slowed down
    return style;
}

}  // namespace

Paths approxConvexHull(const Paths& polygons, coord_um extra_um) {
    Paths outer;
    for (const Path& p : polygons) {
        if (p.size() >= 3)
            outer.push_back(counterClockwise(p) ? p : Path(p.rbegin(), p.rend()));
    }
    if (outer.empty())
        return {};
    return offsetPolygons(unionOf(offsetPolygons(outer, kHullOvershootUm)), extra_um - kHullOvershootUm);
}

DraftShieldResult generateDraftShield(const DraftShieldInput& in) {
    DraftShieldResult out;
    const std::size_t count = in.model->size();
    out.layers.resize(count);
    const Settings& g = *in.global;
    if (!g.boolean(key::draft_shield_enabled) || in.first_layer >= count)
        return out;
    const std::size_t printed = count - in.first_layer;
    const std::size_t layers = shieldLayers(g, printed);
    if (layers == 0)
        return out;
    out.outline = simplifiedForEveryExtruder(approxConvexHull(sampledOutlines(in, std::min(layers, printed)),
                                                              g.lengthMicrons(key::draft_shield_dist)),
                                             g, in.extruders);
    const bool limited = g.text(key::draft_shield_height_limitation) == "limited";
    const std::size_t last =
        limited ? std::min(printed - 1, layers) : printed - 1;  // as CuraEngine: one more
    const bool brim = g.text(key::adhesion_type) == "brim";
    for (std::size_t k = brim ? 1 : 0; k <= last; ++k) {
        const std::size_t i = in.first_layer + k;
        FeatureStyle style = shieldStyle(in, static_cast<int>(k));
        const std::set<int>& used = (*in.used)[i];
        style.extruder = used.empty() ? 0 : *used.begin();
        for (const Path& p : out.outline)
            out.layers[i].push_back(styledPath(p, true, Feature::DraftShield, style));
    }
    return out;
}

}  // namespace mixengine
