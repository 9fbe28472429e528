#pragma once
// Toolpaths of one mesh on every layer: walls, top/bottom skin and sparse infill, from the
// mesh's outlines and its settings (Cura's keys: wall_line_count, wall_line_width_0/_x,
// wall_0_inset, top_layers, bottom_layers, skin_line_width, infill_line_distance,
// infill_line_width, infill_pattern, speed_*).
#include <vector>

#include "settings/Settings.h"
#include "slicing/Slicer.h"
#include "toolpaths/ExtrusionPath.h"

namespace mixengine {

/// Paths of one layer in print order of their groups: inner walls, outer walls, skin, infill.
struct MeshLayerGroups {
    std::vector<ExtrusionPath> inner_walls;
    std::vector<ExtrusionPath> outer_walls;
    std::vector<ExtrusionPath> skin;
    std::vector<ExtrusionPath> infill;
};

std::vector<MeshLayerGroups> generateMeshToolpaths(const std::vector<SlicedLayer>& layers,
                                                   const Settings& settings, int threads);

}  // namespace mixengine
