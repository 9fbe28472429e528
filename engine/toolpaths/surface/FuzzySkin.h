#pragma once
// Fuzzy skin (magic_fuzzy_skin_enabled, _outside_only, _thickness, _point_dist; _point_density acts
// through the formula of _point_dist) as CuraEngine 4.13 makes it: every outer wall loop is redrawn
// through new points about point_dist apart (between 3/4 and 5/4 of it), each moved sideways off the
// line by a random distance in [−thickness, thickness); the first new point comes a random distance
// (below 3/8 point_dist) after the loop's start. With outside_only the holes' loops (clockwise) stay
// as they are. A loop that would keep fewer than three points keeps its own. Not on layer 0 with a
// brim. The randomness is a seeded generator (the layer number and the loop's place), so a slice is
// reproducible and does not depend on the thread count.
#include <cstdint>
#include <vector>

#include "geometry/Point.h"
#include "settings/Settings.h"
#include "toolpaths/core/ExtrusionPath.h"

namespace mixengine {

struct FuzzySkinParams {
    bool enabled = false;
    bool outside_only = false;
    coord_um thickness_um = 300;
    coord_um point_dist_um = 800;
};

FuzzySkinParams fuzzySkinParams(const Settings& s, int layer);

/// One loop made fuzzy; `seed` drives its random numbers.
Path fuzzyLoop(const Path& loop, const FuzzySkinParams& params, std::uint64_t seed);

/// Makes every closed WallOuter path in `paths` fuzzy (layer `layer`).
void applyFuzzySkin(std::vector<ExtrusionPath>& paths, const FuzzySkinParams& params, int layer);

}  // namespace mixengine
