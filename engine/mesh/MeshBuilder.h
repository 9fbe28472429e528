#pragma once
// Turns a triangle soup (millimetres) into a clean indexed Mesh (microns).
//
// Steps: apply the 3x3 transform (mesh_rotation_matrix, may scale), quantise to microns, weld
// vertices that share integer coordinates, drop degenerate faces (two equal indices or zero area)
// and duplicate faces (the same three vertices in any order). Counts of what was dropped are
// reported through `warnings` when non-zero. Inconsistent winding and small gaps are left for the
// slicer, which does not depend on them.
#include <string>
#include <vector>

#include "mesh/Mesh.h"
#include "mesh/ModelReader.h"

namespace mixengine {

/// Row-major 3x3 matrix applied as p' = M * p (Cura's mesh_rotation_matrix, in Cura's axis frame
/// already converted to the engine's: x right, y back, z up).
struct Matrix3 {
    double m[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    Vec3 apply(const Vec3& p) const {
        return {m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z, m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z,
                m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z};
    }
};

struct MeshBuildStats {
    std::size_t input_triangles = 0;
    std::size_t degenerate_dropped = 0;
    std::size_t duplicates_dropped = 0;
    std::size_t welded_vertices = 0;
};

Mesh buildMesh(const TriangleSoup& soup, const Matrix3& transform, MeshBuildStats* stats = nullptr);

}  // namespace mixengine
