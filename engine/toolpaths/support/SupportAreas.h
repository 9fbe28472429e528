#pragma once
// Where support goes, per layer (Cura's support_* keys, CuraEngine 4.13's rules and its order of
// operations, so that its micrometres come out the same; the model's outlines are those the caller
// gives, CuraEngine's print outlines: toolpaths/MeshToolpaths.h, MeshLayerGroups::print_outline):
//   - overhang of layer n: the part of it farther than d = layer_thickness · (tan(support_angle) −
//     0.01) µm, truncated, outside layer n−1 (detectOverhangs; layer 0 rests on the plate); what gets
//     supported is that grown by d + 0.1 mm within layer n, so the strips of consecutive layers join
//     (both offsets mitred, limit 1.2, their input united first);
//   - the overhang of layer n is supported from layer n − top_gap − 1 downwards, top_gap =
//     ceil(support_top_distance / layer_height) empty layers under the model; on the way down each
//     layer's support is united with the one above, closed by support_join_distance (gaps
//     narrower than twice that are filled, mitred joins, so that it does not drift) and smoothed
//     outward (its notches sharper than 135° filled, toolpaths/support/SupportSmoothing.h);
//     then the model itself is cut out (not on layer 0), and after that the model bottom_gap =
//     ceil(support_bottom_distance / layer_height) layers below (the support stops that far above it),
//     on slopes in stairs (toolpaths/support/SupportStairs.h); the support is not simplified (the
//     model is, by 25 µm, for speed: not on the interfaces);
//   - conical support (support_conical_enabled, angle ≠ 0): on the way down the support from above
//     is first shrunk by layer_thickness · (tan(support_conical_angle) − 0.01) (a negative angle
//     grows it by layer_thickness · (tan(−angle) − 0.01)), except its parts narrower than
//     support_conical_min_width, which go down as they are;
//   - then (not propagated, as CuraEngine, so that support next to slopes survives) each layer is
//     grown by support_offset, loses the model grown by support_xy_distance (mitred; with z_overrides_xy:
//     only support_xy_distance_overhang next to the layer's own overhang) and the model top_gap
//     layers up, and islands under minimum_support_area; support_type buildplate keeps only
//     columns that reach the plate; support with no support above or below it is dropped;
//   - towers (params.towers, toolpaths/support/SupportTowers.h): their roofs are added to each layer's
//     support before it is joined with the layer above;
//   - interfaces, as CuraEngine 4.13's generateSupportRoof / generateSupportBottom (roof first, then
//     the floor from what the roof left): on layer i the roof is the support that lies under the
//     model on layers i + top_gap + 1 … i + top_gap + roof_layers, the floor the support over the
//     model on layers i − bottom_gap − floor_layers … i − bottom_gap − 1 (both sampled about every
//     interface_skip_layers layers, as CuraEngine: z_skip = (layers − 1) / max(1, (layers − 1) /
//     skip)); that is grown by the interface's line width (kept within the support), then by its
//     offset (support_roof_offset / support_bottom_offset; kept within the support when growing),
//     and its islands under the minimum area (minimum_roof_area / minimum_bottom_area) are dropped;
//     the body is what is left.
#include <vector>

#include "geometry/Point.h"
#include "slicing/LayerHeights.h"
#include "slicing/Slicer.h"
#include "toolpaths/support/SupportTowers.h"

namespace mixengine {

struct SupportAreaParams {
    int top_gap_layers = 1;
    int bottom_gap_layers = 1;
    coord_um xy_distance_um = 700;
    coord_um xy_distance_overhang_um = 200;
    bool z_overrides_xy = true;
    bool buildplate_only = false;
    coord_um join_distance_um = 0;
    /// the joined area's notches are filled with shortcuts this long (toolpaths/support/SupportSmoothing.h;
    /// CuraEngine's widest of the support, roof and floor lines); 0 = not
    coord_um smoothing_um = 0;
    coord_um offset_um = 0;
    double min_area_um2 = 0;
    int roof_layers = 0;               ///< 0 = no roof interface
    int floor_layers = 0;              ///< 0 = no floor interface
    int interface_skip_layers = 1;     ///< support_interface_skip_height in layers (at least 1)
    coord_um roof_line_width_um = 0;   ///< the roof's margin around the model above
    coord_um floor_line_width_um = 0;  ///< the floor's margin around the model below
    coord_um roof_offset_um = 0;       ///< support_roof_offset
    coord_um floor_offset_um = 0;      ///< support_bottom_offset
    double min_roof_area_um2 = 0;      ///< minimum_roof_area
    double min_floor_area_um2 = 0;     ///< minimum_bottom_area
    /// stair-stepping on slopes (toolpaths/support/SupportStairs.h): step height in layers (1 = off),
    /// width, minimum slope, and the layer height the slopes are measured with
    int stair_step_layers = 1;
    coord_um stair_step_width_um = 5000;
    double stair_min_slope_degrees = 10;
    coord_um layer_height_um = 200;
    coord_um conical_step_um = 0;       ///< conical support: offset per layer going down (0 = off)
    coord_um conical_min_width_um = 0;  ///< narrower parts are not shrunk
    SupportTowerParams towers;          ///< support towers (toolpaths/support/SupportTowers.h); default off
};

struct SupportLayerAreas {
    Paths support;  ///< the support's body (interfaces excluded)
    Paths roof;     ///< interface right under the model
    Paths floor;    ///< interface right on the model
};

struct Overhangs {
    std::vector<Paths> basic;  ///< [layer] not supported by the layer below
    std::vector<Paths> full;   ///< [layer] basic grown by d + 0.1 mm within the layer: to support
    /// [layer] overhang points: small parts with nothing under them, where towers start
    /// (toolpaths/support/SupportTowers.h); may be empty (no towers)
    std::vector<std::vector<Paths>> points;
};

/// Per layer the overhangs of `layers` (angle in degrees from vertical). `blockers` (may be null):
/// per layer the support blockers' area, taken out of the basic overhang (as CuraEngine 4.13: the
/// full overhang grows from what is left).
Overhangs detectOverhangs(const std::vector<SlicedLayer>& layers, const std::vector<LayerZ>& heights,
                          double angle_degrees, int threads, const std::vector<Paths>* blockers = nullptr);

/// The support meshes' areas per layer: `drop_down` (support_mesh_drop_down) is carried down to the
/// plate or the model, `in_place` stays on its layer; both are handled apart from the overhangs'
/// support, as CuraEngine's support-mesh placeholder (no support_offset).
struct SupportMeshAreas {
    std::vector<Paths> drop_down;  ///< [layer], or empty
    std::vector<Paths> in_place;   ///< [layer], or empty
};

/// `model[n]`: every mesh's outlines on layer n (united); `overhangs`: those of the meshes with
/// support_enable, united per layer.
std::vector<SupportLayerAreas> computeSupportAreas(const std::vector<Paths>& model,
                                                   const Overhangs& overhangs,
                                                   const SupportAreaParams& params, int threads,
                                                   const SupportMeshAreas& meshes = {});

}  // namespace mixengine
