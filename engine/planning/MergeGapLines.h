#pragma once
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
#include <functional>

#include "planning/LayerPlan.h"

namespace mixengine {

struct GapMergeParams {
    coord_um nozzle_um = 400;        ///< machine_nozzle_size
    coord_um max_deviation_um = 25;  ///< meshfix_maximum_deviation
};

/// Merges the mergeable gap lines of `layer` as above; `params` gives an extruder's values, and
/// `extruder` is the one active when the layer starts (SetExtruder steps change it).
void mergeGapLines(PlannedLayer& layer, int extruder, const std::function<GapMergeParams(int)>& params);

}  // namespace mixengine
