#pragma once
// The raft under a mesh group (adhesion_type raft), as CuraEngine 4.13 prints it
// (toolpaths/adhesion/RaftLayout.h gives the layers' numbers and heights):
//   outline   — everything on the model's first layer (models, support, prime tower) grown by
//               raft_margin with round corners, then closed by raft_smoothing (grown and shrunk by
//               it, round): small holes and inward corners disappear;
//   base      — a loop raft_base_line_width/2 inside the outline, then lines along Y (0°)
//               raft_base_line_spacing apart reaching that loop;
//   interface — zigzag raft_interface_line_spacing apart at 45° (90° without surface layers) in the
//               outline shrunk by raft_interface_line_width/2;
//   surface k — (k = 1 … raft_surface_layers) zigzag raft_surface_line_spacing apart at 90°·k in the
//               outline shrunk by raft_surface_line_width/2;
//   the zigzags print their end pieces without their last lines (toolpaths/infill/ZigZag.h, ZigzagEnds::
//   Open), as CuraEngine's raft zigzag (end pieces on, not connected).
// Each layer has its width (raft_*_line_width, no initial-layer factor), speed (raft_*_speed, no
// first-layer slow-down), flow 100 %, fan (raft_*_fan_speed) and its own Feature (RaftBase,
// RaftInterface, RaftSurface: ;TYPE:SUPPORT-INTERFACE, SUPPORT, SUPPORT-INTERFACE), all from the
// adhesion_extruder_nr train, which prints the whole raft. Line grids are anchored at the plate's
// origin (toolpaths/infill/LineInfill.h) and loops are simplified with that train's
// meshfix_maximum_resolution / _deviation.
#include <vector>

#include "geometry/Point.h"
#include "settings/Settings.h"
#include "toolpaths/adhesion/RaftLayout.h"
#include "toolpaths/core/ExtrusionPath.h"

namespace mixengine {

/// A layer printed below the model: a raft layer or a filler layer (toolpaths/adhesion/RaftLayout.h).
struct RaftLayer {
    int index = 0;  ///< CuraEngine's (negative) layer number
    coord_um z_um = 0;
    coord_um thickness_um = 0;
    /// The raft layer's fan (raft_*_fan_speed, 0..1); a filler layer (negative) cools as the
    /// model's first layer does.
    double fan_ratio = -1;
    std::vector<ExtrusionPath> paths;
};

struct RaftInput {
    const Settings* global = nullptr;
    const std::vector<Settings>* extruders = nullptr;
    Paths first_layer;  ///< the models' outlines, the support area and the prime tower on layer 0
};

struct RaftToolpaths {
    Paths outline;                  ///< what the raft covers (empty without a raft)
    std::vector<RaftLayer> layers;  ///< base, interface, surface layers, in print order
};

/// The raft's outline: `first_layer` grown by `margin_um`, then closed by `smoothing_um`.
Paths raftOutline(const Paths& first_layer, coord_um margin_um, coord_um smoothing_um);

/// The raft layers (none unless adhesion_type is raft or when nothing is on the first layer).
RaftToolpaths generateRaft(const RaftInput& input);

}  // namespace mixengine
