#pragma once
// Where travel may go on a layer (microns): the comb area, inside which travel needs no
// retraction (combArea: per mesh by its retraction_combing mode, even-odd, planning/CombBoundary.h),
// and with travel_avoid_other_parts the space around the parts that through-air travel may use
// (freeSpace; planning/TravelRoute.h). They depend on the layer's toolpaths alone.
#include <cstddef>

#include "geometry/Point.h"
#include "geometry/PolygonOps.h"
#include "planning/CombBoundary.h"
#include "toolpaths/GroupToolpaths.h"

namespace mixengine {

/// The outlines of every mesh's sliced layer toolpaths.first_sliced_layer + layer, one after the
/// other (microns). As CuraEngine 4.13's print outline: a mesh with support_enable, walls and without
/// fill_outline_gaps is outlined by its outer walls grown by half their width (parts too thin for an
/// outer wall are left out).
Paths partOutlines(const GroupToolpaths& toolpaths, std::size_t layer);

/// Where travel on `layer` of `toolpaths` may go without retraction: every mesh's comb area for its
/// retraction_combing mode (MeshLayerGroups::comb_area), or its sliced outlines ("all").
Paths combArea(const GroupToolpaths& toolpaths, std::size_t layer);

/// The space through-air travel may use with travel_avoid_other_parts: a rectangle 5 mm around the
/// parts, less the parts grown by `avoid_distance_um` (mitred, as CuraEngine 4.13's Comb grows its
/// outside boundary), as even-odd loops (rectangle first). `loops`: Loops::United when the outlines
/// are one mesh's (a union already), so they are not united again.
Paths freeSpace(const Paths& outlines, coord_um avoid_distance_um, Loops loops = Loops::Any);

/// Where travel on a model layer may go: its comb area and (travel_avoid_other_parts) the space
/// around its parts. They depend on the layer's toolpaths alone, so the planner makes them ahead
/// (common/ComputedAhead.h).
struct LayerBoundaries {
    CombBoundary comb, free;
};

/// Layer `i`'s boundaries; free is empty without outlines.
LayerBoundaries layerBoundaries(const GroupToolpaths& toolpaths, std::size_t i, coord_um avoid_distance_um);

}  // namespace mixengine
