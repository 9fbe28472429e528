#pragma once
// The mix schedule: which mix a layer gets from its height (seed 001, generalised to stops).
//
// For stops s0..sn (heights non-decreasing) and a layer at height h:
//   h <= s0.height              → s0's mix                  (seed case 1: "A only")
//   sk.height < h <= sk+1.height → linear from sk to sk+1    (seed case 2)
//   h > sn.height               → sn's mix                  (seed case 3: "B only")
// Two stops at the same height give a hard switch there (seed: colorA == colorB): layers at or
// below it take the first mix, layers above it the second.
#include <vector>

#include "mixing/setup/MixingSettings.h"

namespace mixengine {

/// The mix at `height` (same unit as the stops' heights). `stops` must not be empty.
MixVector mixAtHeight(const std::vector<GradientStop>& stops, double height);

/// The mix of a layer whose top is `layer_top_mm` above the mesh's bottom, for a mesh
/// `mesh_height_mm` tall: the fixed mix in dual and color mode, the gradient (in percent of the mesh
/// height, or in mm) in gradient mode.
MixVector targetMix(const MeshMixing& mixing, double layer_top_mm, double mesh_height_mm);

}  // namespace mixengine
