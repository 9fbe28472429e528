#pragma once
// Painted facets of PrusaSlicer and OrcaSlicer 3MF files, which lib3mf does not read: the triangle
// attributes slic3rpe:mmu_segmentation (PrusaSlicer) and paint_color (OrcaSlicer) in
// 3D/3dmodel.model, read with libzip and a small tag scanner.
//
// The attribute holds the facet's paint as hex digits read from the end: a digit whose low two bits
// are 0 is a whole facet, painted with extruder (digit >> 2), 3 meaning "3 + the next digit"; other
// digits split the facet into (low bits + 1) sub-facets, each encoded the same way. A facet painted
// in parts takes the extruder most of its sub-facets carry (the sub-facet geometry is not kept).
// Extruder 0 is "not painted". Files without such attributes give an empty map.
#include <cstdint>
#include <filesystem>
#include <map>
#include <string_view>
#include <vector>

namespace mixengine {

/// The extruder painted on a facet (0 = none) from its attribute value; malformed text gives 0.
int paintedExtruder(std::string_view encoded);

/// For each object id of the main model part: the painted extruder of each of its triangles, in
/// file order (0 = not painted). Only objects with at least one painted triangle are listed.
std::map<std::uint32_t, std::vector<int>> readPaintedFacets(const std::filesystem::path& file);

}  // namespace mixengine
