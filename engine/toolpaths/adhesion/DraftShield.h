#pragma once
// Draft shield (draft_shield_enabled), as CuraEngine 4.13 prints it: one wall around the whole
// print, draft_shield_dist outside the approximate convex hull (toolpaths/adhesion/DraftShield.h
// approxConvexHull) of the models and the support on every (500 µm / layer_height + 1)-th layer
// of the shield's height, simplified with the extruders' largest meshfix_maximum_resolution and smallest
// meshfix_maximum_deviation; the same outline on every layer from the first up to
// (draft_shield_height − layer_height_0) / layer_height + 1 with draft_shield_height_limitation
// limited, else on every layer. Printed first on its layer (before the ooze shield's turn ends,
// after the skirt or brim), by the first extruder printing on the layer, in the style of extruder
// 0's skirt and brim (skirt_brim_line_width, skirt_brim_speed, skirt_brim_material_flow), Feature
// DraftShield (marked SKIRT). With adhesion_type brim the first layer has no shield: the brim
// fills the shield's foot instead (toolpaths/adhesion/Adhesion.h).
#include <cstddef>
#include <set>
#include <vector>

#include "geometry/Point.h"
#include "settings/Settings.h"
#include "toolpaths/core/ExtrusionPath.h"

namespace mixengine {

struct DraftShieldInput {
    const Settings* global = nullptr;
    const std::vector<Settings>* extruders = nullptr;
    const std::vector<Paths>* model = nullptr;                         ///< [layer] every mesh's outlines
    const std::vector<std::vector<ExtrusionPath>>* support = nullptr;  ///< [layer]
    const std::vector<std::set<int>>* used = nullptr;                  ///< [layer] extruders printing
    std::size_t first_layer = 0;  ///< the first layer that prints (the empty ones below are dropped)
};

struct DraftShieldResult {
    Paths outline;                                   ///< empty without a draft shield
    std::vector<std::vector<ExtrusionPath>> layers;  ///< [layer] as the input's layers
};

DraftShieldResult generateDraftShield(const DraftShieldInput& input);

/// CuraEngine's approximate convex hull: the outer contours grown by 100 mm and shrunk back by
/// 100 mm − `extra_um` (round joins), so that concave parts narrower than 200 mm are closed.
Paths approxConvexHull(const Paths& polygons, coord_um extra_um);

}  // namespace mixengine
