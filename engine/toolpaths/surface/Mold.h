#pragma once
// Mold (mold_enabled, mold_width, mold_roof_height, mold_angle) as CuraEngine 4.13 makes it from a
// mesh group's sliced outlines, from the top layer down: each mold mesh's layer becomes its outline
// (open pieces thickened to the outer wall's width, × initial_layer_line_width_factor on layer 0)
// grown by mold_width (round joins) — with mold_angle below 90° united with the mold's outline on the
// layer above shrunk by tan(mold_angle) × layer_height, so the mold's outside slopes — plus, above
// layer 0, a roof: the outline mold_roof_height / layer_height layers below grown by mold_width. Then
// the outlines of every mold mesh's model on that layer are cut out of every mold, so the model
// becomes the mold's cavity.
#include <vector>

#include "settings/Settings.h"
#include "slicing/Slicer.h"

namespace mixengine {

/// One mesh of the group: its sliced layers and resolved settings.
struct MoldMesh {
    std::vector<SlicedLayer>* layers = nullptr;
    const Settings* settings = nullptr;
};

/// Turns every mesh with mold_enabled into its mold; `layer_height_um`: the group's layer_height.
void applyMolds(const std::vector<MoldMesh>& meshes, coord_um layer_height_um);

}  // namespace mixengine
