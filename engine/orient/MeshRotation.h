#pragma once
// Applying the orientation pass's rotation to meshes, and writing them (mixengine orient --write).
#include <string>
#include <vector>

#include "geometry/Matrix3.h"
#include "mesh/Mesh.h"

namespace mixengine::orient {

/// Rotates every mesh about `centre_mm` (p' = c + R (p − c), rounded to microns), then moves all
/// of them by one vertical step so that their common lowest point is where it was before.
void rotateTogether(const std::vector<Mesh*>& meshes, const Matrix3& rotation, const Vec3& centre_mm);

/// One mesh made of several (vertices and faces appended; no welding across meshes).
Mesh concatenated(const std::vector<const Mesh*>& meshes, const std::string& name);

/// A binary STL file's bytes (facet normals from the corners, millimetres).
std::string binaryStl(const Mesh& mesh);

}  // namespace mixengine::orient
