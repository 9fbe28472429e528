#pragma once
// Top and bottom skin areas, as CuraEngine 4.13 computes them per layer i:
//   top skin    = inner_area[i] minus the area present in every one of layers i+1 … i+top_layers
//                 (all of inner_area[i] within top_layers of the mesh's top);
//   bottom skin = inner_area[i] minus the area present in every one of layers i-bottom_layers …
//                 i-1 (all of it on the first initial_bottom_layers layers);
// where a layer's "present" area is a reference region chosen as CuraEngine 4.13 does
// (skinReference): the innermost wall's centre region, moved out one wall (and then to the
// outline) for as long as the skin removal width (top/bottom_skin_preshrink) covers the distance
// (a width within 10 µm of a wall's centre ends there), grown by what is left of the removal width.
// So the skin loses that much along the covered area (only there: a narrow neck with air above
// stays skin); it is then grown by the expand distance (top/bottom_skin_expand_distance) plus the
// removal width left over — only its parts at least min_skin_width_for_expansion wide when that is
// set — and clipped to inner_area[i]. The union is the skin; pieces under 0.16 mm² are dropped.
// With min_infill_area, covering pieces smaller than it do not count as covering (what they would
// cover becomes skin). The infill area is inner_area[i] minus the skin, less its parts narrower
// than infill_line_width (pieces under 0.16 mm² dropped). With roofing_layer_count > 0 (at most
// top_layers), the part of the skin with air within roofing_layer_count layers above is roofing, as
// CuraEngine 4.13 finds it: "no air above" is the roofing reference region (the centre region of
// wall min(2, wall count)) of every layer up to roofing_layer_count above, plus where that region
// has nothing of it on the layer below (air below: such skin stays skin). With
// skin_no_small_gaps_heuristic each window counts by its farthest layer alone (i+top_layers,
// i-bottom_layers, i+roofing_layers) instead of the intersection of all its layers.
//
// The "present in every layer of a window" intersections come from toolpaths/core/LayerWindows.h.
#include <vector>

#include "geometry/Point.h"

namespace mixengine {

/// The reference region (0 = outline, k = centre region of wall k) for a removal width, and the
/// part of the removal width left for removing narrow skin.
struct SkinReference {
    int wall = 0;
    coord_um leftover_preshrink_um = 0;
};

SkinReference skinReference(coord_um preshrink_um, int wall_count, coord_um outer_width_um,
                            coord_um inner_width_um);

struct SkinParams {
    int top_layers = 0;
    int bottom_layers = 0;
    int initial_bottom_layers = 0;
    coord_um top_preshrink_um = 0;  ///< what is left of the removal width (skinReference): the
                                    ///< reference regions grow by it
    coord_um bottom_preshrink_um = 0;
    coord_um top_expand_um = 0;
    coord_um bottom_expand_um = 0;
    coord_um min_width_for_expansion_um = 0;
    int roofing_layers = 0;
    double min_infill_area_um2 = 0;
    /// skin_no_small_gaps_heuristic: compare with the farthest layer of each window only.
    bool small_gaps_heuristic = false;
    /// Also find the outer surfaces (SkinAreas::outer_surfaces), against the roofing reference.
    bool outer_surfaces = false;
    /// As CuraEngine: the infill area loses what is narrower than this (infill_line_width).
    coord_um infill_opening_um = 0;
};

struct SkinAreas {
    Paths skin;  ///< solid area, roofing included (its loops run around both, as CuraEngine's skin parts)
    /// The part of `skin` with air above, to be printed as roofing inside the skin's loops (empty
    /// unless roofing_layers > 0); the rest of the skin is printed as skin.
    Paths roofing;
    Paths infill;  ///< sparse infill area
    /// With SkinParams::outer_surfaces, the skin with air directly above (as roofing with one
    /// layer) or directly below (nothing of the roofing reference on the layer below; all of it on
    /// layer 0): CuraEngine's top- and bottom-most surfaces.
    Paths outer_surfaces;
};

/// The regions each layer's skin is compared with (see above), index = layer.
/// Each layer's regions as a Clipper union returns them (Loops::United; WallResult's references are).
struct SkinReferenceRegions {
    const std::vector<Paths>* top = nullptr;
    const std::vector<Paths>* bottom = nullptr;
    const std::vector<Paths>* roofing = nullptr;  ///< nullptr: the top reference
};

/// Per layer i: the reference regions, and `inner_areas[i]` the area inside the innermost walls.
std::vector<SkinAreas> computeSkinAreas(const SkinReferenceRegions& references,
                                        const std::vector<Paths>& inner_areas, const SkinParams& params,
                                        int threads);

}  // namespace mixengine
