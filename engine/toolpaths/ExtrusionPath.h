#pragma once
// The output of toolpath generation: typed extrusion lines per layer, plain data.
#include <cstdint>
#include <string_view>
#include <vector>

#include "geometry/Point.h"

namespace mixengine {

/// Feature types, named as Cura's ;TYPE: markers name them.
enum class Feature { WallOuter, WallInner, Skin, Fill, Support, SupportInterface, Skirt, PrimeTower };

std::string_view featureMarker(Feature feature);  ///< "WALL-OUTER", "FILL", ...

struct ExtrusionPath {
    Path points;            ///< microns
    bool closed = false;    ///< a loop: the printer returns to points.front()
    coord_um width_um = 0;  ///< line width
    Feature feature = Feature::Fill;
    double speed_mm_s = 0;
    double flow = 1.0;         ///< multiplier on the nominal width × thickness volume
    int extruder = 0;          ///< extruder train that prints it
    bool fixed_start = false;  ///< a loop whose seam is chosen (z_seam_type): print from points.front()
    /// 0, or the number of a sequence: the paths of a group with the same non-zero sequence are
    /// printed one after the other in list order once the first of them is reached (a monotonic
    /// skin); the planner still picks which end of each line to start from.
    std::uint32_t sequence = 0;
};

}  // namespace mixengine
