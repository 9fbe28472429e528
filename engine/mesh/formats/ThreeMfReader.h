#pragma once
// 3MF input through lib3mf 1.8 (its plain C interface, Model/COM/NMR_DLLInterfaces.h).
//
// One triangle soup per build item, named after the item's object (or "<file stem>_<n>" for the
// n-th build item when its object has no name). Component objects are flattened with their component
// transforms; the build item's transform is applied on top, then the model's unit attribute is converted to
// millimetres. Painted triangles (colorgroup colours, basematerials display colours, PrusaSlicer/OrcaSlicer
// painted facets: mesh/formats/ThreeMfPaint.h) give TriangleSoup::colors. lib3mf's reader warnings are passed
// on. InputError (naming the file): unreadable archive or model, non-finite coordinates, components nested
// deeper than 32 levels, no triangles at all.
#include <filesystem>
#include <string>
#include <vector>

#include "mesh/formats/ModelReader.h"

namespace mixengine {

std::vector<TriangleSoup> readThreeMf(const std::filesystem::path& file, std::vector<std::string>& warnings);

}  // namespace mixengine
