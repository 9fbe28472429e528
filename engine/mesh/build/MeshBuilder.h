#pragma once
// Turns a triangle soup (millimetres) into a clean indexed Mesh (microns).
//
// Steps: apply the 3x3 transform (mesh_rotation_matrix, may scale), quantise to microns
// (llround of mm * 1000), weld vertices that share integer coordinates, drop degenerate faces (two
// equal corners or zero area in integer space) and duplicate faces (the same three vertices in any
// order or winding); a painted soup's colours follow the faces kept (Mesh::face_colors). Counts of what was
// dropped are returned in MeshBuildStats; the caller turns non-zero counts into warnings. Inconsistent
// winding and small gaps are left for the slicer, which does not depend on them.
//
// Guarantees: every vertex is used by a kept face; vertices are numbered in order of first use and
// faces keep the soup's order, so the result is deterministic. O(n) time (hash tables, no
// allocation per triangle). Throws InputError naming the part (`label`, or soup.name when empty) when
// a transformed coordinate is not finite or lies outside +-1 km, or when there are more than 2^32/3
// triangles.
#include <string>
#include <vector>

#include "geometry/Matrix3.h"
#include "mesh/Mesh.h"
#include "mesh/formats/ModelReader.h"

namespace mixengine {

struct MeshBuildStats {
    std::size_t input_triangles = 0;     ///< triangles in the soup
    std::size_t degenerate_dropped = 0;  ///< zero-area faces removed
    std::size_t duplicates_dropped = 0;  ///< faces repeating an earlier face's vertex set
    std::size_t welded_vertices = 0;     ///< distinct vertices of the result (mesh.vertices.size())
};

Mesh buildMesh(const TriangleSoup& soup, const Matrix3& transform, MeshBuildStats* stats = nullptr,
               const std::string& label = {});

}  // namespace mixengine
