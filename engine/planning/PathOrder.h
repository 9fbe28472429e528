#pragma once
// Orders the extrusion paths of one layer to keep travel short and turns them into plan steps.
//
// Greedy nearest neighbour from the current head position: a closed loop may start at any of its
// vertices (the nearest is taken), an open line at either end. A sequence (ExtrusionPath::sequence)
// is entered at its first path only and then printed in list order, each line from its end nearer
// to the head. Travels longer than
// retraction_min_travel retract when retraction is enabled, unless they stay inside the comb
// boundary (combing).
#include <optional>
#include <vector>

#include "planning/CombBoundary.h"
#include "planning/LayerPlan.h"
#include "toolpaths/ExtrusionPath.h"

namespace mixengine {

struct TravelParams {
    double travel_speed_mm_s = 150;
    bool retraction_enable = true;
    coord_um retraction_min_travel_um = 1500;
    coord_um layer_thickness_um = 200;
    const CombBoundary* comb = nullptr;  ///< travels that stay inside it are not retracted
    coord_um wall_0_wipe_um = 0;         ///< wall_0_wipe_dist: travel on along an outer wall loop's start
    coord_um infill_wipe_um = 0;         ///< infill_wipe_dist: travel on past the end of an infill line
};

/// Appends the steps for `paths` (one group, printed together) to `steps`, starting from and
/// updating `head`; a ;TYPE: step is added whenever the feature differs from `feature`.
void appendOrderedPaths(std::vector<ExtrusionPath> paths, const TravelParams& params, Point2& head,
                        std::optional<Feature>& feature, std::vector<PlanStep>& steps);

/// The volume of a line: length × width × layer thickness × flow, in mm³.
double extrusionVolumeMm3(const Point2& from, const Point2& to, coord_um width_um, coord_um thickness_um,
                          double flow);

}  // namespace mixengine
