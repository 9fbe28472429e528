#include "toolpaths/surface/ConicalOverhang.h"

#include <cmath>
#include <numbers>

#include "geometry/Clip.h"
#include "geometry/PolygonOps.h"

namespace mixengine {
namespace {

constexpr coord_um kSafeDistanceUm = 20;

/// The layer above less the small holes of `layer` that it covers completely.
Paths withSmallHolesKept(const Paths& layer, Paths above, double max_hole_area_mm2) {
    if (max_hole_area_mm2 <= 0)
        return above;
    for (const Paths& island : splitIslands(layer)) {
        for (const Path& loop : island) {
            if (counterClockwise(loop))
                continue;  // the contour
            const Paths hole{loop};
            if (std::abs(signedAreaUm2(loop)) / 1e6 >= max_hole_area_mm2)
                continue;
            if (intersectAll(hole, above).empty())
                continue;
            if (std::abs(areaUm2(differenceOf(hole, above))) <= 0.0)
                above = differenceOf(above, hole);
        }
    }
    return above;
}

}  // namespace

bool conicalOverhangWanted(const Settings& s) {
    return s.boolean(key::conical_overhang_enabled);
}

ConicalOverhangParams conicalOverhangParams(const Settings& s) {
    ConicalOverhangParams p;
    p.angle_degrees = s.angleDegrees(key::conical_overhang_angle);
    p.max_hole_area_mm2 = s.real(key::conical_overhang_hole_size);
    p.layer_height_um = s.lengthMicrons(key::layer_height);
    return p;
}

void applyConicalOverhang(std::vector<SlicedLayer>& layers, const ConicalOverhangParams& params) {
    if (layers.size() < 2)
        return;
    const double tangent = std::tan(params.angle_degrees * std::numbers::pi / 180.0);
    const auto shrink = static_cast<coord_um>(tangent * double(params.layer_height_um));
    for (std::size_t i = layers.size() - 1; i-- > 0;) {
        Paths& layer = layers[i].outlines;
        const Paths& above = layers[i + 1].outlines;
        if (std::llabs(shrink) < 5) {
            const Paths added = differenceOf(above, offsetMiter(layer, -kSafeDistanceUm));
            layer = cleanPolygons(unionOf(layer, added), kSafeDistanceUm);
            continue;
        }
        layer =
            unionOf(layer, offsetMiter(withSmallHolesKept(layer, above, params.max_hole_area_mm2), -shrink));
    }
}

}  // namespace mixengine
