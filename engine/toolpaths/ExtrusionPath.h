#pragma once
// The output of toolpath generation: typed extrusion lines per layer, plain data.
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
    double flow = 1.0;  ///< multiplier on the nominal width × thickness volume
};

/// Everything one mesh prints on one layer, in print order once planned.
struct MeshLayerPaths {
    int mesh_index = 0;
    int extruder = 0;
    std::vector<ExtrusionPath> paths;
};

struct LayerToolpaths {
    int index = 0;                       ///< 0-based layer number (;LAYER:n)
    coord_um print_z = 0;                ///< nozzle height
    coord_um thickness_um = 0;           ///< slab thickness (for the extruded volume)
    std::vector<ExtrusionPath> nonmesh;  ///< skirt / brim (;MESH:NONMESH)
    std::vector<MeshLayerPaths> meshes;
};

}  // namespace mixengine
