#pragma once
// Where a raft's layers go and how far it lifts the model, as CuraEngine 4.13 computes them
// (adhesion_type raft; the raft_* keys are read from the adhesion_extruder_nr train):
//   raft layers   — one base (raft_base_thickness), one interface (raft_interface_thickness) and
//                   raft_surface_layers surface layers (raft_surface_thickness each), stacked from
//                   the plate; their total is the raft's thickness T;
//   gap           — G = max(0, raft_airgap + layer_height_0 − layer_0_z_overlap): from the raft's
//                   top to the bottom of the model's layer 1;
//   filler layers — round(G / layer_height) of them, each round(G / count) thick, between the raft
//                   and the model; they print only the first layer's support (if any);
//   numbering     — the model's layers keep 0, 1, …; the layers below count down from −1: filler
//                   layers −1 … −F, then the surface, interface and base layers, so the base is
//                   layer −(2 + raft_surface_layers + F);
//   model heights — every model layer is raised by T + raft_airgap − layer_0_z_overlap, the first
//                   one by T + raft_airgap (it sinks into the air gap less than the others).
// Everything is in integer microns; `enabled` false (any other adhesion_type) gives no layers and
// no lift.
#include <vector>

#include "geometry/Point.h"
#include "settings/Settings.h"

namespace mixengine {

struct RaftLayout {
    bool enabled = false;
    int extruder = 0;  ///< adhesion_extruder_nr
    coord_um base_thickness_um = 0;
    coord_um interface_thickness_um = 0;
    coord_um surface_thickness_um = 0;
    int surface_layers = 0;
    coord_um airgap_um = 0;
    coord_um layer_0_overlap_um = 0;  ///< layer_0_z_overlap
    coord_um layer_height_0_um = 0;
    coord_um layer_height_um = 0;

    /// T: base + interface + surface_layers × surface thickness (0 without a raft).
    coord_um totalThicknessUm() const;
    /// G: from the raft's top to the bottom of the model's layer 1 (0 without a raft).
    coord_um gapUm() const;
    int fillerLayerCount() const;
    coord_um fillerLayerHeightUm() const;
    /// 2 + raft_surface_layers + filler layers (0 without a raft).
    int extraLayerCount() const;
    /// How far model layer `layer` (0, 1, …) is lifted.
    coord_um modelLiftUm(int layer) const;
};

/// The raft's layout for a mesh group with `global` settings and its extruder trains.
RaftLayout raftLayout(const Settings& global, const std::vector<Settings>* extruders);

}  // namespace mixengine
