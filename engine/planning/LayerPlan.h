#pragma once
// The output of planning: for every layer, the ordered steps the print head takes. Plain data;
// the G-code writer turns it into text without making any decisions of its own.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "geometry/Point.h"
#include "planning/MixVector.h"
#include "toolpaths/core/ExtrusionPath.h"

namespace mixengine {

struct PlanStep {
    enum class Kind {
        Travel,                ///< move without extruding to `to`; `retract` says whether to retract first
        Extrude,               ///< move to `to` while extruding `volume_mm3`
        SetFeature,            ///< ;TYPE: marker
        SetMesh,               ///< ;MESH: marker (mesh_index −1 = NONMESH)
        SetFan,                ///< fan to `fan_ratio` (0..1)
        SetExtruder,           ///< tool change to `extruder`
        SetNozzleTemperature,  ///< `temperature_c` for nozzle `extruder` (−1: the active one); `wait`: M109
        SetBedTemperature,     ///< M140 `temperature_c`, without waiting
        /// cool_lift_head on a layer too short even slowed down: retract, lift the head 3 mm, travel
        /// to `to` at `speed_mm_s` and wait `dwell_seconds` (G4)
        LiftHead,
        Prime,  ///< first use of the active extruder: its prime (G280 on Griffin), then a retraction
        /// clean_between_layers: the wipe script of extruder `extruder` (gcode/WipeScript.h), where
        /// the head is; it returns there
        WipeScript,
    };
    Kind kind = Kind::Travel;
    Point2 to{};
    double speed_mm_s = 0;
    double volume_mm3 = 0;
    bool retract = false;
    bool prime_first = false;  ///< Travel: prime (unretract) before it (the last move onto an outer wall)
    Feature feature = Feature::Fill;
    int mesh_index = -1;
    double fan_ratio = 0;
    int extruder = 0;  ///< SetExtruder: the new one; SetNozzleTemperature: the nozzle (−1 = active)
    double temperature_c = 0;
    double dwell_seconds = 0;       ///< LiftHead
    bool wait = false;              ///< SetNozzleTemperature: wait until it is reached (M109)
    double acceleration_mm_s2 = 0;  ///< Travel/Extrude: M204 before the move when it changes (0 = none)
    double jerk_mm_s = 0;           ///< Travel/Extrude: M205 before the move when it changes (0 = none)
    int mix = -1;                   ///< Extrude: index into PrintPlan::mixes (mixing/MixingPass.h); -1 = none
    /// Extrude: the colour predicted to leave the nozzle (index into PrintPlan::outlet_colors; -1 = none)
    int outlet_color = -1;
    /// Extrude (spiralize): the nozzle ends the move this far above the layer's z (0 = at the height
    /// it is at); a spiral rises along its moves (toolpaths/surface/Spiralize.h).
    coord_um rise_um = 0;

    coord_um width_um = 0;   ///< Extrude: the line width of the path it belongs to
    bool bridge = false;     ///< SetFeature: printed with bridge settings (;BRIDGE)
    bool fan_fixed = false;  ///< SetFan: a bridge's own fan_ratio, kept by cooling
    bool mergeable = false;  ///< Extrude: of a gap line (ExtrusionPath::mergeable)
};

struct PlannedLayer {
    /// CuraEngine's layer number: 0 is the model's first layer; raft and raft filler layers below
    /// it are negative (;LAYER:-6 … ;LAYER:-1).
    int index = 0;
    coord_um z = 0;          ///< nozzle height
    coord_um thickness = 0;  ///< height of the extruded lines (0 = the distance to the layer below)
    std::vector<PlanStep> steps;
    /// The travel step that retract_at_layer_change made retract (−1: none); a wipe script at the
    /// layer's start takes the place of that retraction (planning/LayerWipes.h).
    int layer_change_retract_step = -1;
};

struct PrintPlan {
    std::vector<PlannedLayer> layers;
    std::vector<std::string> mesh_names;  ///< for ;MESH: markers
    std::vector<MixVector> mixes;         ///< filled by the mixing stage; empty in single mode
    /// The distinct 8-bit sRGB colours predicted to leave the nozzle (mixing/transition/OutletPrediction.h)
    std::vector<std::array<std::uint8_t, 3>> outlet_colors;
};

}  // namespace mixengine
