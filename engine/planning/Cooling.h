#pragma once
// Cooling of one planned layer, with Cura's keys, as CuraEngine 4.13 does it (ExtruderPlan::
// processFanSpeedAndMinimalLayerTime / forceMinimalLayerTime), on its naive estimate (estimateLayer):
//   - minimum layer time: when the layer would take less than cool_min_layer_time, every
//     extrusion is slowed by the same factor so that the extrusions take cool_min_layer_time minus
//     the travel time (at least 1 s); when that would bring the slowest extrusion under
//     cool_min_speed, the factor is the one that prints it at cool_min_speed (travel keeps its
//     speed);
//   - fan: from cool_fan_full_layer on, cool_fan_speed_max for layers whose estimate (before the
//     slow-down, retracted travel left out) is under cool_min_layer_time, else cool_fan_speed_min
//     for layers that take at least cool_min_layer_time_fan_speed_max, linear in between; before
//     that layer a ramp from cool_fan_speed_0 (layers below the model — raft filler layers — count
//     as layer 0);
//   - raft layers (raftCooling): their raft_*_fan_speed replaces cool_fan_speed_min and there is no
//     ramp, as CuraEngine 4.13 cools them; the minimum layer time and cool_fan_speed_max still apply;
//   - cool_lift_head: when the layer still takes more than 0.1 s less than cool_min_layer_time once
//     slowed down, the layer ends with a LiftHead step (as CuraEngine 4.13: retract, lift 3 mm, move
//     20 mm towards the middle of the bed, wait out the rest).
#include <functional>
#include <vector>

#include "planning/LayerPlan.h"
#include "settings/Settings.h"

namespace mixengine {

struct CoolingParams {
    bool fan_enabled = true;
    double fan_min_ratio = 1.0;  ///< cool_fan_speed_min
    double fan_max_ratio = 1.0;  ///< cool_fan_speed_max
    double fan_first_ratio = 0;  ///< cool_fan_speed_0
    int fan_full_layer = 2;      ///< cool_fan_full_layer (1-based as in Cura)
    double min_layer_time_s = 5;
    double fan_max_layer_time_s = 10;  ///< cool_min_layer_time_fan_speed_max
    double min_speed_mm_s = 10;
    bool lift_head = false;      ///< cool_lift_head
    Point2 bed_middle_um{0, 0};  ///< where the lifted head moves towards
    double travel_speed_mm_s = 150;
    /// What a retracted travel adds to the estimate: retraction_amount / retraction_retract_speed
    /// of the layer's (last) extruder, 0 without retraction (coolingParams takes the global ones).
    double retract_seconds = 0;
};

/// CuraEngine 4.13's naive estimate of a layer (ExtruderPlan::computeNaiveTimeEstimates): every
/// move's distance / speed; the travel the layer starts with counts as one straight unretracted
/// move from the head's start to where it ends (CuraEngine estimates a layer before it plans the
/// travel that connects it to the one below); each later retracted travel adds retract_seconds.
struct LayerEstimate {
    double extrude_s = 0;      ///< extrusions
    double travel_s = 0;       ///< travel and retractions
    double unretracted_s = 0;  ///< travel that does not retract, and half of each retraction
};

/// The estimate of `layer` (see LayerEstimate), the head at `start`.
LayerEstimate estimateLayer(const PlannedLayer& layer, Point2 start, double retract_seconds);

CoolingParams coolingParams(const Settings& settings);

/// retraction_amount / retraction_retract_speed of an extruder (0 when it does not retract).
double retractSeconds(const Settings& extruder);

/// The model's cooling for a raft layer printed with `raft_fan_ratio` (0..1).
CoolingParams raftCooling(const CoolingParams& model, double raft_fan_ratio);

/// Seconds each step takes at its planned speed (index = step; 0 for markers), the head at `start`.
std::vector<double> stepSeconds(const PlannedLayer& layer, Point2 start);

/// Seconds the layer's moves take at their planned speeds (distance / speed, from `start`).
double naiveLayerSeconds(const PlannedLayer& layer, Point2 start);

/// Slows the layer down and sets its fan (the layer's SetFan steps) as described above; the
/// estimate is estimateLayer(layer, start, params.retract_seconds).
void applyCooling(PlannedLayer& layer, Point2 start, const CoolingParams& params);

// The merging of short gap-fill lines, as CuraEngine 4.13 merges a layer's lines before its time
// estimate (LayerPlan::optimizePaths, MergeInfillLines). CuraEngine's rules let only the lines that
// fill the gaps between a part's walls and between its walls and its skin or infill merge (the
// skin's own lines and the infill's never do); here those are the Extrude steps with
// PlanStep::mergeable. Walking the layer's paths in print order (a path: the Extrude steps between
// two travels), each single-segment gap line that a travel leads to and leaves is tried against the
// last one taken (or the merged line it grew into):
//   - lines nearly in line with each other whose ends meet (within a line width) stay apart;
//   - otherwise, when the midpoint of the second lies within 5 line widths of the first's midpoint
//     (or of the merged line's end) and both lines lie within 1.5 line widths of the line joining
//     them, the pair becomes one line from the first's mean point to the second's midpoint, or the
//     merged line gains the second's midpoint (replacing its last point when the error stays under
//     a line width squared, as CuraEngine's mean-deviation check allows); the travel before the
//     first now ends at its mean point, the travel between and the second line go;
//   - the merged line keeps the volume of both (its flow is their length × flow over the merged
//     length CuraEngine predicts), and no merge makes it wider than 3 nozzles.
// Travel before and after the merged line keep their retraction; nothing else changes.

/// What merging takes from an extruder's settings.
struct GapMergeParams {
    coord_um nozzle_um = 400;        ///< machine_nozzle_size
    coord_um max_deviation_um = 25;  ///< meshfix_maximum_deviation
};

/// Merges the mergeable gap lines of `layer` as above; `params` gives an extruder's values, and
/// `extruder` is the one active when the layer starts (SetExtruder steps change it).
void mergeGapLines(PlannedLayer& layer, int extruder, const std::function<GapMergeParams(int)>& params);

}  // namespace mixengine
