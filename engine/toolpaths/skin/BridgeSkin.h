#pragma once
// Bridged skin, as CuraEngine 4.13 finds and prints it (bridge_settings_enabled; src/bridge.cpp):
// a skin part of layer i whose area resting on the layer below — that layer's outline, less its
// sparse infill area when the infill is no denser than bridge_sparse_infill_max_density
// (infill_line_width / infill_line_distance) — is under bridge_skin_support_threshold of its own
// area is a bridge. Its lines run along its longest edge over air (the layer below's outline
// left out, as seen from far around the part, shrunk 10 µm), else along the line between the
// centres of the two largest areas it rests on (1 to 5 of them), else at the skin angle; they are
// lines, bridge_skin_density apart as a fraction of a line width, reach
// max(skin_overlap_mm, wall_line_width_x / 2) beyond the part, and are printed at
// bridge_skin_speed with bridge_skin_material_flow and the fan at bridge_fan_speed, marked ;BRIDGE.
// With bridge_enable_more_layers a part that is not a bridge over layer i−1 is tested against
// layer i−2 (from layer 2 on, bottom_layers > 1: the second bridge layer, _2 settings, lines 45°
// from the bridge angle, 90° when bottom_layers is 2), then against i−3 (layer 3 on,
// bottom_layers > 2: _3 settings, 135°); there the sparse infill counts as support.
// Only the mesh's own layers are looked at (not other meshes' or support below).
#include <optional>
#include <vector>

#include "settings/Settings.h"
#include "toolpaths/skin/SkinPaths.h"

namespace mixengine {

struct BridgeSkinLayer {
    double speed_mm_s = 0;
    double flow = 1.0;
    double density = 1.0;
    double fan_ratio = 1.0;
};

struct BridgeSkinParams {
    bool enabled = false;
    bool more_layers = false;
    double support_threshold = 0.5;  ///< bridge_skin_support_threshold (fraction)
    bool sparse_infill = true;       ///< the infill below is sparse enough to count as air
    int bottom_layers = 0;
    coord_um overlap_um = 0;    ///< max(skin_overlap_mm, wall_line_width_x / 2)
    BridgeSkinLayer layers[3];  ///< first, second and third bridge layer
};

BridgeSkinParams bridgeSkinParams(const Settings& s);

/// What lies below layer `layer` (outlines[i] and infill[i] per layer, microns).
struct LayersBelow {
    const std::vector<Paths>* outlines = nullptr;
    const std::vector<Paths>* infill = nullptr;
    int layer = 0;
};

/// The fill of skin part `part` on a bridge (from `skin`, the layer's own skin fill), or none.
std::optional<SkinFillParams> bridgeSkinFill(const Paths& part, const SkinFillParams& skin,
                                             const BridgeSkinParams& params, const LayersBelow& below);

/// The line angle CuraEngine gives part `part` resting on `solid_below` (−1: none); `islands` is
/// the part of `part` on it.
int bridgeLineAngle(const Paths& part, const Paths& solid_below, const Paths& islands);

}  // namespace mixengine
