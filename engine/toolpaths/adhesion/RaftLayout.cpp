#include "toolpaths/adhesion/RaftLayout.h"

#include <algorithm>

#include "toolpaths/support/Support.h"

namespace mixengine {
namespace {

/// a / b rounded half up, as CuraEngine's round_divide (a ≥ 0, b > 0).
coord_um roundDivide(coord_um a, coord_um b) {
    return (a + b / 2) / b;
}

}  // namespace

coord_um RaftLayout::totalThicknessUm() const {
    if (!enabled)
        return 0;
    return base_thickness_um + interface_thickness_um + coord_um(surface_layers) * surface_thickness_um;
}

coord_um RaftLayout::gapUm() const {
    if (!enabled)
        return 0;
    return std::max<coord_um>(0, std::max<coord_um>(0, airgap_um) + layer_height_0_um - layer_0_overlap_um);
}

int RaftLayout::fillerLayerCount() const {
    if (!enabled || layer_height_um <= 0)
        return 0;
    return static_cast<int>(roundDivide(gapUm(), layer_height_um));
}

coord_um RaftLayout::fillerLayerHeightUm() const {
    const int count = fillerLayerCount();
    return count > 0 ? roundDivide(gapUm(), count) : layer_height_um;
}

int RaftLayout::extraLayerCount() const {
    return enabled ? 2 + surface_layers + fillerLayerCount() : 0;
}

coord_um RaftLayout::modelLiftUm(int layer) const {
    if (!enabled)
        return 0;
    const coord_um lift = totalThicknessUm() + airgap_um;
    return layer == 0 ? lift : lift - layer_0_overlap_um;
}

RaftLayout raftLayout(const Settings& global, const std::vector<Settings>* extruders) {
    RaftLayout layout;
    layout.enabled = global.text(key::adhesion_type) == "raft";
    if (!layout.enabled)
        return layout;
    const int nr = global.extruderIndex(key::adhesion_extruder_nr);
    layout.extruder = std::max(nr, 0);
    const Settings& s = trainSettings(global, extruders, layout.extruder);
    layout.base_thickness_um = s.lengthMicrons(key::raft_base_thickness);
    layout.interface_thickness_um = s.lengthMicrons(key::raft_interface_thickness);
    layout.surface_thickness_um = s.lengthMicrons(key::raft_surface_thickness);
    layout.surface_layers =
        static_cast<int>(std::clamp<long long>(s.integer(key::raft_surface_layers), 0, 1000));
    layout.airgap_um = s.lengthMicrons(key::raft_airgap);
    layout.layer_0_overlap_um = s.lengthMicrons(key::layer_0_z_overlap);
    layout.layer_height_0_um = global.lengthMicrons(key::layer_height_0);
    layout.layer_height_um = global.lengthMicrons(key::layer_height);
    return layout;
}

}  // namespace mixengine
