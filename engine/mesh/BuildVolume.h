#pragma once
// The check of a placed mesh against the printer's build volume (the box of machine_width,
// machine_depth and machine_height, from 0 or centred on 0 as machine_center_is_zero says).
//
// Contract of checkBuildVolume():
//   - a mesh inside the volume: returns an empty string;
//   - a mesh reaching outside it: returns one warning line naming the mesh and both boxes. The mesh
//     is sliced as placed (CuraEngine 4.13's command line does the same; only what lies above z = 0
//     can print);
//   - a mesh placed (by machine_width / machine_depth / mesh_position_*) beyond 1 km from the
//     origin, which slicing cannot represent exactly: throws InputError naming the mesh and those
//     settings;
//   - a mesh more than kMaxOversize times the volume's size along some axis (a 500 m cube for a
//     100 mm printer: almost always metres or inches read as millimetres, and slicing it would run
//     for hours): throws InputError naming the mesh, both sizes and the machine settings.
#include <string>

#include "mesh/Mesh.h"

namespace mixengine {

constexpr double kMaxOversize = 10.0;

struct BuildVolume {
    Point3 min;  ///< microns
    Point3 max;  ///< microns
};

/// The build volume of a machine: width, depth and height in microns, centred in XY on 0 or not.
BuildVolume machineVolume(coord_um width, coord_um depth, coord_um height, bool center_is_zero);

std::string checkBuildVolume(const std::string& name, const AABB3& mesh_box, const BuildVolume& volume);

}  // namespace mixengine
