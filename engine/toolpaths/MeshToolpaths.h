#pragma once
// Toolpaths of one mesh on every layer: walls (toolpaths/walls/Walls.h, seams by toolpaths/walls/Seam.h),
// top/bottom skin and roofing (toolpaths/skin/Skin.h) and sparse infill (toolpaths/infill/InfillPatterns.h),
// from the mesh's outlines and its resolved settings (Cura's keys and meanings):
//   walls   — wall_line_count, wall_line_width_0/_x, wall_0_inset, z_seam_*; with
//             optimize_wall_printing_order each outline's loops are one sequence (toolpaths/walls/Walls.h);
//   skin    — top_layers, bottom_layers, initial_bottom_layers, skin removal / expansion widths;
//             per skin part skin_outline_count loops of skin_line_width, inside them the roofing
//             (roofing_layer_count: roofing_pattern at roofing_angles[layer % n], default 45°,
//             135°, roofing_monotonic) and the skin (top_bottom_pattern, on layer 0
//             top_bottom_pattern_0, at skin_angles[layer % n], default 45°, 135°, reaching
//             skin_overlap_mm beyond its area, skin_monotonic), and with fill_perimeter_gaps the
//             gaps of concentric skin (toolpaths/skin/SkinPaths.h);
//   infill  — the infill area arranged by toolpaths/infill/InfillLayers.h (infill as support, gradual
//             infill, combined layers) and printed by toolpaths/infill/MeshInfill.h (infill_pattern at
//             infill_line_distance, its origin at the mesh's middle moved by infill_offset_x/_y);
//             none when infill_line_distance is 0;
//   outline gaps — with fill_outline_gaps, the gaps between the outline and the outer wall
//             (toolpaths/walls/OutlineGaps.h), first in the skin group, in the perimeter gaps' style
//             with the outer wall's extruder;
//   ironing — with ironing_enabled, the layer's top surface (toolpaths/surface/Ironing.h), last.
// With magic_mesh_surface_mode "surface" the outlines (and open pieces) are printed once along
// themselves as outer wall, and nothing else.
// Widths, speeds, flows and extruders per feature and layer: toolpaths/core/FeatureStyle.h.
// Layers are processed in parallel (common/ParallelFor.h); the result does not depend on `threads`.
#include <optional>
#include <vector>

#include "common/WorkProgress.h"

#include "settings/Settings.h"
#include "slicing/Slicer.h"
#include "toolpaths/core/ExtrusionPath.h"
#include "toolpaths/skin/Skin.h"

namespace mixengine {

/// Paths of one layer in print order of their groups: inner walls, outer walls, skin, infill,
/// ironing.
struct MeshLayerGroups {
    std::vector<ExtrusionPath> inner_walls;
    std::vector<ExtrusionPath> outer_walls;
    std::vector<ExtrusionPath> skin;
    std::vector<ExtrusionPath> infill;
    /// Where travel may comb on this layer for the mesh's retraction_combing mode, as CuraEngine
    /// 4.13's comb boundary; none = its sliced outlines ("off", and "all" without parts). "all":
    /// per part inside the second wall's centre line (the outer wall's where there is no second
    /// wall); no_outer_surfaces: that less the skin with air directly above or below; noskin: per
    /// part the ring from the outer wall's inner edge to just inside the innermost wall, and the
    /// infill area; infill: the infill area.
    std::optional<Paths> comb_area;
    std::vector<ExtrusionPath> ironing;
    /// infill_randomize_start_location: planning starts the infill nearest this point.
    std::optional<Point2> infill_start;
    /// CuraEngine's layer parts: the islands of the outline the walls are made from, each its outer
    /// contour first, then the holes directly inside it (disjoint areas). Every path of the layer
    /// lies in one of them (planning prints them part by part, planning/order/PartOrder.h). Empty in
    /// magic_mesh_surface_mode "surface".
    std::vector<Paths> parts;
    /// CuraEngine 4.13's print outline, the model's outline as its support sees it (overhangs, the
    /// model cut out, x/y distance, interfaces): with support_enable, no fill_outline_gaps and walls,
    /// the outer wall's centre region (Walls.h: WallResult::outer_region) grown by half the outer
    /// wall's width with squared corners, so a right-angled corner is cut 0.29 widths off and a part
    /// too thin for a wall has none. Unset: the sliced outlines are that.
    std::optional<Paths> print_outline;
    /// z_seam_type "back": the seam position (z_seam_relative applied), where CuraEngine starts
    /// looking for the first part; unset for the other seam types.
    std::optional<Point2> seam_position;
};

/// Whether the outer walls go before the inner ones on `layer`: outer_inset_first, and (as
/// CuraEngine 4.13) always on layer 0 with a brim.
bool outerWallFirst(const Settings& s, int layer);

/// A mesh half done, in two steps as CuraEngine 4.13 works so that infill meshes can take part of
/// the infill of the meshes before them (toolpaths/InfillMeshes.h): the walls (in `walls`, the
/// other groups still empty), the areas left inside them, the skin areas, and the infill area the
/// mesh prints with its own pattern (`own_infill`; at first the skin areas' infill).
struct MeshAreas {
    std::vector<MeshLayerGroups> walls;  ///< [layer] inner and outer walls only
    std::vector<Paths> inner_areas;      ///< [layer] inside the innermost wall
    std::vector<Paths> wall_gaps;        ///< [layer] the gaps between the walls
    std::vector<Paths> outline_gaps;     ///< [layer] fill_outline_gaps: between outline and outer wall
    std::vector<SkinAreas> skin;         ///< [layer]
    std::vector<Paths> own_infill;       ///< [layer]
    std::vector<Paths> spiral_loops;     ///< [layer] magic_spiralize: the spiral's wall loops (else empty)
};

/// Step 1: walls and areas (not for magic_mesh_surface_mode "surface": see surfaceOnlyMesh).
/// `progress` hears of every layer done (and may throw to stop the work).
MeshAreas generateMeshAreas(const std::vector<SlicedLayer>& layers, const Settings& settings, int threads,
                            const WorkProgress& progress);

/// Step 2: the skin, infill (in `own_infill`) and ironing lines added to the walls. Perimeter gaps
/// and combing see the skin areas' infill, not `own_infill`, as CuraEngine's.
std::vector<MeshLayerGroups> generateMeshPaths(MeshAreas areas, const std::vector<SlicedLayer>& layers,
                                               const Settings& settings, int threads,
                                               const std::optional<Box2>& mesh_box_um,
                                               const WorkProgress& progress);

/// magic_mesh_surface_mode "surface": generateMeshToolpaths prints the outlines alone.
bool surfaceOnlyMesh(const Settings& settings);

/// Both steps (or the surface alone).
/// `mesh_box_um`: the mesh's bounding box in x and y (its middle is CuraEngine's infill origin, the
/// cross fractal's square is laid around it); without it, the bounds of all its outlines.
std::vector<MeshLayerGroups> generateMeshToolpaths(const std::vector<SlicedLayer>& layers,
                                                   const Settings& settings, int threads,
                                                   const std::optional<Box2>& mesh_box_um = std::nullopt);

}  // namespace mixengine
