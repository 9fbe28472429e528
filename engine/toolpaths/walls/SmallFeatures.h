#pragma once
// Small features as CuraEngine 4.13 prints them (LayerPlan::addWall): a wall loop shorter all round
// than small_feature_max_length prints at small_feature_speed_factor (small_feature_speed_factor_0
// on the first layer) of its speed, but never under cool_min_speed.
#include <vector>

#include "settings/Settings.h"
#include "toolpaths/core/ExtrusionPath.h"

namespace mixengine {

struct SmallFeatureParams {
    coord_um max_length_um = 0;  ///< small_feature_max_length; 0 = off
    double speed_factor = 1;     ///< small_feature_speed_factor(_0), as a fraction
    double min_speed_mm_s = 0;   ///< cool_min_speed
};

SmallFeatureParams smallFeatureParams(const Settings& mesh, int layer);

/// Slows the closed paths of `walls` whose length all round is under the maximum, as above.
void slowSmallFeatures(std::vector<ExtrusionPath>& walls, const SmallFeatureParams& params);

}  // namespace mixengine
