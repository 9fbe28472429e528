#include "toolpaths/walls/SmallFeatures.h"

#include <algorithm>

#include "geometry/PolygonOps.h"

namespace mixengine {

SmallFeatureParams smallFeatureParams(const Settings& s, int layer) {
    SmallFeatureParams p;
    p.max_length_um = s.lengthMicrons(key::small_feature_max_length);
    p.speed_factor =
        s.ratio(layer == 0 ? key::small_feature_speed_factor_0 : key::small_feature_speed_factor);
    p.min_speed_mm_s = s.velocityMmPerS(key::cool_min_speed);
    return p;
}

void slowSmallFeatures(std::vector<ExtrusionPath>& walls, const SmallFeatureParams& p) {
    if (p.max_length_um <= 0)
        return;
    for (ExtrusionPath& wall : walls) {
        if (!wall.closed || wall.speed_mm_s <= 0 || lengthUm(wall.points, true) >= double(p.max_length_um))
            continue;
        wall.speed_mm_s *= std::max(p.speed_factor, p.min_speed_mm_s / wall.speed_mm_s);
    }
}

}  // namespace mixengine
