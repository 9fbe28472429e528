#pragma once
// Toolpaths of one mesh on every layer: walls (toolpaths/Walls.h, seams by toolpaths/Seam.h),
// top/bottom skin and roofing (toolpaths/Skin.h) and sparse infill (toolpaths/InfillPatterns.h),
// from the mesh's outlines and its resolved settings (Cura's keys and meanings):
//   walls   — wall_line_count, wall_line_width_0/_x, wall_0_inset, z_seam_*;
//   skin    — top_layers, bottom_layers, initial_bottom_layers, skin removal / expansion widths,
//             skin_outline_count loops of skin_line_width, then lines (top_bottom_pattern, on layer
//             0 top_bottom_pattern_0) at skin_angles[layer % n] (default 45°, 135°) reaching
//             skin_overlap_mm beyond the skin area; roofing (roofing_layer_count) likewise with the
//             roofing_* keys;
//   infill  — the infill area arranged by toolpaths/InfillLayers.h (infill as support, gradual
//             infill, combined layers) and printed by toolpaths/MeshInfill.h (infill_pattern at
//             infill_line_distance, its origin at the mesh's middle moved by infill_offset_x/_y);
//             none when infill_line_distance is 0;
//   ironing — with ironing_enabled, the layer's top surface (toolpaths/Ironing.h), last.
// Widths, speeds, flows and extruders per feature and layer: toolpaths/FeatureStyle.h.
// Layers are processed in parallel (common/ParallelFor.h); the result does not depend on `threads`.
#include <optional>
#include <vector>

#include "settings/Settings.h"
#include "slicing/Slicer.h"
#include "toolpaths/ExtrusionPath.h"

namespace mixengine {

/// Paths of one layer in print order of their groups: inner walls, outer walls, skin, infill,
/// ironing.
struct MeshLayerGroups {
    std::vector<ExtrusionPath> inner_walls;
    std::vector<ExtrusionPath> outer_walls;
    std::vector<ExtrusionPath> skin;
    std::vector<ExtrusionPath> infill;
    std::vector<ExtrusionPath> ironing;
    /// infill_randomize_start_location: planning starts the infill nearest this point.
    std::optional<Point2> infill_start;
};

/// `mesh_middle_um`: the middle of the mesh's bounding box in x and y (CuraEngine's infill origin);
/// without it, the middle of the bounds of all its outlines.
std::vector<MeshLayerGroups> generateMeshToolpaths(
    const std::vector<SlicedLayer>& layers, const Settings& settings, int threads,
    const std::optional<Point2>& mesh_middle_um = std::nullopt);

}  // namespace mixengine
