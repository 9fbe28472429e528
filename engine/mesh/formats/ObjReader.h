#pragma once
// Wavefront OBJ input: `v x y z [...]` and `f a b c ...` statements, one triangle soup per
// `o`/`g` group that has faces (faces before any group belong to a part named after the file
// stem; a group name seen again continues its part).
//
// Face corners may be written `v`, `v/vt`, `v//vn` or `v/vt/vn`; only the vertex index is used.
// Negative indices count back from the last vertex defined so far; positive ones may refer to a
// vertex defined later in the file. Polygons are fan-triangulated. Other statements (vt, vn, s,
// usemtl, mtllib, l, ...) and `#` comments are ignored.
//
// InputError (naming the file and the 1-based line): non-numeric or non-finite vertex coordinate,
// a face corner that is not an integer, an index of 0 or out of range, a face with fewer than 3
// corners; and "contains no triangles" when no face is left.
#include <filesystem>
#include <string>
#include <vector>

#include "mesh/formats/ModelReader.h"

namespace mixengine {

std::vector<TriangleSoup> readObj(const std::filesystem::path& file, std::vector<std::string>& warnings);

}  // namespace mixengine
