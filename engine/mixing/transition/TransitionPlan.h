#pragma once
// Transition planning over a whole plan (issue 26), for prints whose mix changes inside a layer:
//
//  1. every layer is reordered by mix (mixing/transition/LayerOrder.h);
//  2. the commanded mix of each extrusion: a visible one gets the mix it asks for; a hidden one the
//     mix of the next visible extrusion of its layer (it absorbs the change), or of the last one when
//     none follows; in a layer without visible extrusions (the raft, support alone) its own;
//  3. before each run of visible extrusions the chamber (mixing/chamber/ChamberModel.h) is asked how much of
//     the new mix must still flow before what leaves the nozzle is within the tolerance; that much is
//     purged into the tower (mixing/transition/PurgeTower.h), so the run prints within the tolerance. The
//     tower's square is sized from a first pass for the largest layer purge; every layer up to the last purge
//     prints the whole square, the excess going into that layer's last purge.
//
// The planned volumes are exact in the model: nothing is over-extruded on the part, and a purge is
// never more than the model needs (plus the tower's excess in layers that need less than its square).
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "mixing/chamber/ChamberModel.h"
#include "mixing/transition/LayerOrder.h"
#include "mixing/transition/PurgeTower.h"

namespace mixengine {

struct TransitionSettings {
    ChamberSpec chamber;
    double tolerance = 0.1;  ///< mixing_transition_tolerance (shareDistance)
    bool tower = true;       ///< mixing_purge_tower_enable
    TowerSite site;          ///< the print's own rectangle is filled in from the plan
    std::optional<Chamber>
        incoming;  ///< the chamber as earlier groups left it (empty: full of the first mix)
    std::optional<std::pair<Point2, Point2>>
        keep_clear;  ///< printed before (one at a time): the tower avoids it
    coord_um line_width_um = 400;
    double speed_mm_s = 30;  ///< the tower's print speed
    /// The tower's speed on a layer (by ;LAYER: number), e.g. slower on the first layers; empty: speed_mm_s
    std::function<double(int layer_number)> speed_at;
    int threads = 1;  ///< threads the planner may use (the leading planner tries purge sites side by side)
};

struct TransitionReport {
    int changes = 0;  ///< runs of visible extrusions that needed a change of the chamber
    int layers_with_changes = 0;
    double purge_mm3 = 0;          ///< printed into the tower
    double needed_mm3 = 0;         ///< what the changes needed beyond the hidden volume (first pass)
    double looser_needed_mm3 = 0;  ///< the same at twice the tolerance
    double unpurged_mm3 = 0;       ///< needed but not purged (no tower, or no room for one)
    double full_change_mm3 = 0;  ///< one change from one filament to another (the physical minimum per layer)
    std::optional<PurgeTowerShape> tower;
    std::vector<std::string> warnings;
};

/// Plans the transitions of `plan` in place: reorders layers, inserts the tower, sets every
/// extrusion's PlanStep::mix. `targets[l][i]` is step i of layer l's target; it is updated to the
/// new steps (−1 mixes for inserted steps, the tower's included).
TransitionReport planTransitions(PrintPlan& plan, std::vector<std::vector<StepTarget>>& targets,
                                 const TransitionSettings& settings);

}  // namespace mixengine
