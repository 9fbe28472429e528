#pragma once
// Transition planning for continuous fields (issue 27): a gradient along X, Y or radially, a feathered
// edge — visible extrusions that ask for their own mix (StepTarget::exact) every few mm³. Stepping the
// chamber band by band and purging until each band is reached (mixing/transition/TransitionPlan.h) costs a
// purge of several times the model; leading the chamber costs a fraction of it:
//
//  1. the layers come ordered by band (mixing/transition/LayerOrder.h), so each layer sweeps the field once
//  and the
//     next sweeps it back;
//  2. every extrusion, and every piece of the purge, gets the command that lets the outlet follow the
//     field where it shows (mixing/transition/LeadCommands.h): ahead of the field, overshooting in hidden
//     extrusions;
//  3. what cannot be followed is where a sweep turns at a layer's start: there the tower is visited, as
//     much as needed. The purge per mm of layer height is the smallest of 0, ¼, ½, ¾, 1, 1½ and 2 full
//     changes (fullChangeVolumeMm3, per the print's usual layer height) that brings the visible
//     surface within the tolerance — 98 % of it by volume, or within 2 points of the best the ladder
//     reaches when that is less (the rest of a purge buys little; the report says what is left);
//  4. the tower is visited at the start of every layer up to the last one that changes, its whole
//     square at once, and the commands are found again over the print as it will be written.
#include <vector>

#include "mixing/transition/LayerOrder.h"
#include "mixing/transition/TransitionPlan.h"

namespace mixengine {

/// Whether some visible extrusion asks for a continuous field's own mix, or some hidden one for its
/// model's core mix (mixing_core_ratio: wished for with a small weight, so the core takes its ratio
/// wherever that costs the visible surface nothing).
bool needsLeading(const std::vector<std::vector<StepTarget>>& targets);

/// Plans a plan whose layers are ordered by mix (planTransitions does that first): inserts the tower
/// visits, sets every extrusion's PlanStep::mix (new mixes are added to plan.mixes) and updates
/// `targets` to the new steps. `report.full_change_mm3` is read; the rest is filled in.
void planLeading(PrintPlan& plan, std::vector<std::vector<StepTarget>>& targets,
                 const TransitionSettings& settings, TransitionReport& report);

}  // namespace mixengine
