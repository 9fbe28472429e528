#pragma once
// Mesh input: reads STL (binary and ASCII), OBJ and 3MF files into triangle soups, one per part.
//
// Contract:
//   - readModelFile() throws InputError with one line naming the file and the defect when the file
//     cannot give any triangle (missing, empty, truncated, non-numeric, NaN/Inf coordinates, ...).
//   - Recoverable defects (face-count mismatch with intact triangle data, trailing bytes, several
//     `solid` blocks, wrong normals) add a line to `warnings` and the file is read.
//   - Coordinates are returned in millimetres as stored in the file (no transform, no welding).
//   - STL gives one part; OBJ gives one part per `o`/`g` group that has faces; 3MF one per object
//     (build items with their transforms applied).
#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "geometry/Point.h"

namespace mixengine {

struct TriangleSoup {
    std::string name;                            ///< part name (file stem, OBJ group or 3MF object name)
    std::vector<std::array<Vec3, 3>> triangles;  ///< millimetres
    /// Per triangle (3MF only): 0 = not painted, else as Mesh::face_colors; empty = none painted.
    std::vector<std::uint32_t> colors;
};

std::vector<TriangleSoup> readModelFile(const std::filesystem::path& file,
                                        std::vector<std::string>& warnings);

}  // namespace mixengine
