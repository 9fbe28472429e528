#pragma once
// "Make overhang printable" (conical_overhang_enabled, conical_overhang_angle,
// conical_overhang_hole_size) as CuraEngine 4.13 applies it to a mesh's sliced outlines, from the
// top layer down: each layer becomes its union with the (already widened) layer above shrunk by
// tan(angle) × layer_height, so no overhang is steeper than the angle. A hole of the layer below an
// area smaller than hole_size mm² that the layer above covers completely is cut out of the layer
// above first (it stays a hole instead of being filled by a cone). When the shrink is under 5 µm
// the layer above is added as it is (less a 20 µm margin) and the result is cleaned at 20 µm.
#include <vector>

#include "settings/Settings.h"
#include "slicing/Slicer.h"

namespace mixengine {

struct ConicalOverhangParams {
    double angle_degrees = 50;
    double max_hole_area_mm2 = 0;
    coord_um layer_height_um = 200;
};

/// From the mesh's settings; none when conical_overhang_enabled is off.
bool conicalOverhangWanted(const Settings& s);
ConicalOverhangParams conicalOverhangParams(const Settings& s);

void applyConicalOverhang(std::vector<SlicedLayer>& layers, const ConicalOverhangParams& params);

}  // namespace mixengine
