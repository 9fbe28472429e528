#include "toolpaths/walls/OverhangWalls.h"

#include <cmath>
#include <numbers>

#include "geometry/PointQueries.h"
#include "geometry/PolygonOps.h"

namespace mixengine {
namespace {

constexpr coord_um kMaskSlackUm = 10;  // CuraEngine's 10 µm around the supported region

}  // namespace

OverhangWallParams overhangWallParams(const Settings& s) {
    OverhangWallParams p;
    const double angle_degrees = s.number(key::wall_overhang_angle);
    p.enabled = angle_degrees < 90;
    if (!p.enabled)
        return p;
    p.tan_angle = std::tan(angle_degrees / (180 / std::numbers::pi));  // as CuraEngine divides
    p.outer_width_um = s.lengthMicrons(key::wall_line_width_0);
    p.speed_factor = s.ratio(key::wall_overhang_speed_factor);
    p.small_feature_max_um = s.lengthMicrons(key::small_feature_max_length);
    return p;
}

Paths overhangWallMask(const Paths& outlines, const Paths& outlines_below, coord_um thickness_um,
                       const OverhangWallParams& params) {
    const coord_um half = params.outer_width_um / 2;
    const auto overhang_um = static_cast<coord_um>(double(thickness_um) * params.tan_angle);
    const Paths below = offsetMiter(offsetMiter(outlines_below, -half), half);
    const Paths region =
        differenceOf(offsetMiter(outlines, -half), offsetMiter(below, kMaskSlackUm + overhang_um - half));
    return region.empty() ? Paths{} : offsetMiter(region, kMaskSlackUm);
}

void markOverhangingWalls(std::vector<ExtrusionPath>& walls, const Paths& mask,
                          const OverhangWallParams& params) {
    if (mask.empty())
        return;
    for (ExtrusionPath& wall : walls) {
        if (!wall.closed || wall.points.size() < 3)
            continue;
        std::vector<std::uint8_t> flags(wall.points.size(), 0);
        bool any = false;
        for (std::size_t k = 0; k < wall.points.size(); ++k) {
            flags[k] = insideArea(mask, wall.points[k], true) ? 1 : 0;
            any = any || flags[k] != 0;
        }
        if (!any)
            continue;
        wall.overhanging = std::move(flags);
        const bool small = params.small_feature_max_um > 0 &&
                           lengthUm(wall.points, true) < double(params.small_feature_max_um);
        wall.overhang_speed_factor = small ? 1.0 : params.speed_factor;
    }
}

}  // namespace mixengine
