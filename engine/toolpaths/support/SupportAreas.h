#pragma once
// Where support goes, per layer (Cura's support_* keys, CuraEngine 4.13's rules):
//   - overhang of layer n: the part of it farther than d = layer_thickness · (tan(support_angle) −
//     0.01) outside layer n−1 (detectOverhangs; layer 0 rests on the plate); what gets supported is
//     that grown by d + 0.1 mm within layer n, so the strips of consecutive layers join;
//   - the overhang of layer n is supported from layer n − top_gap − 1 downwards, top_gap =
//     ceil(support_top_distance / layer_height) empty layers under the model; on the way down each
//     layer's support is united with the one above, closed by support_join_distance (gaps
//     narrower than twice that are filled, mitred joins, so that it does not drift) and smoothed
//     outward (its notches sharper than 135° filled, toolpaths/support/SupportSmoothing.h);
//     the model itself is cut out on the way down, and so is the model bottom_gap =
//     ceil(support_bottom_distance / layer_height) layers below (the support stops that far above it);
//   - conical support (support_conical_enabled, angle ≠ 0): on the way down the support from above
//     is first shrunk by layer_thickness · (tan(support_conical_angle) − 0.01) (a negative angle
//     grows it by layer_thickness · (tan(−angle) − 0.01)), except its parts narrower than
//     support_conical_min_width, which go down as they are;
//   - then (not propagated, as CuraEngine, so that support next to slopes survives) each layer is
//     grown by support_offset, loses the model grown by support_xy_distance (with z_overrides_xy:
//     only support_xy_distance_overhang next to the layer's own overhang) and the model top_gap
//     layers up, and islands under minimum_support_area; support_type buildplate keeps only
//     columns that reach the plate; support with no support above or below it is dropped;
//   - stair steps (stair_layers s > 1), as CuraEngine 4.13 rests support on slopes: every s-th layer
//     i (i mod s = 0) the model of layer i − bottom_gap − s + 1, where it lies on a slope and within
//     support_bottom_stair_step_width of the model of layer i − bottom_gap − 1, is taken out of the
//     support of the layers below i as well (so the support stands on the slope in steps s layers
//     high); the slopes of layer n are where the bands slope_band inside layer n−1's outline and
//     slope_band outside layer n's meet, summed over the layers of each step;
//   - towers (params.towers, toolpaths/support/SupportTowers.h): their roofs are added to each layer's
//     support before it is joined with the layer above;
//   - interfaces: the top roof_layers of support under the model are roof, the bottom
//     floor_layers on the model are floor (support_roof_height / support_bottom_height in layers);
//     as CuraEngine 4.13, the roof is then grown by support_roof_offset (mitred; a positive offset kept
//     within the support), and roof and floor islands smaller than minimum_roof_area /
//     minimum_bottom_area stay plain support.
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
    int roof_layers = 0;                ///< 0 = no roof interface
    int floor_layers = 0;               ///< 0 = no floor interface
    coord_um roof_offset_um = 0;        ///< support_roof_offset: the roof grown (within the support)
    double min_roof_area_um2 = 0;       ///< minimum_roof_area: smaller roof islands stay support
    double min_floor_area_um2 = 0;      ///< minimum_bottom_area: smaller floor islands stay support
    int stair_layers = 1;               ///< support_bottom_stair_step_height in layers, + 1 (1 = no stairs)
    coord_um stair_width_um = 0;        ///< support_bottom_stair_step_width
    coord_um slope_band_um = 0;         ///< how wide a slope between two layers is looked for (see above)
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
