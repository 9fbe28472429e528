#pragma once
// An indexed triangle mesh in microns, the output of mesh input and the input of slicing.
//
// Contract:
//   - vertices are welded (no two vertices share the same integer coordinates);
//   - faces index into vertices, three distinct indices each, counter-clockwise seen from outside
//     when the source winding was consistent (slicing does not rely on winding);
//   - degenerate (zero-area) and duplicate faces have been removed by buildMesh (mesh/build/MeshBuilder.h).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "geometry/Point.h"

namespace mixengine {

struct Face {
    std::array<std::uint32_t, 3> v{};
};

struct AABB3 {
    Point3 min{INT64_MAX, INT64_MAX, INT64_MAX};
    Point3 max{INT64_MIN, INT64_MIN, INT64_MIN};
    bool empty() const { return min.x > max.x; }
};

struct Mesh {
    std::string name;  ///< shown in ;MESH: markers (CLI: the -l path; Cura: the object's name)
    std::vector<Point3> vertices;
    std::vector<Face> faces;
    /// Painted colour of each face (3MF colour/material properties, PrusaSlicer/OrcaSlicer painted
    /// facets): 0 = not painted, kPaintedRgb | 0xRRGGBB (a colour), or kPaintedExtruder | n
    /// (painted with extruder n ≥ 1 in PrusaSlicer/OrcaSlicer). Empty when no face is painted.
    std::vector<std::uint32_t> face_colors;
    static constexpr std::uint32_t kPaintedRgb = 0x01000000;
    static constexpr std::uint32_t kPaintedExtruder = 0x02000000;

    AABB3 bounds() const;
    /// Moves every vertex by (dx, dy, dz) microns.
    void translate(coord_um dx, coord_um dy, coord_um dz);
};

}  // namespace mixengine
