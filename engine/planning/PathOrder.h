#pragma once
// Orders the extrusion paths of one layer to keep travel short and turns them into plan steps.
//
// Greedy nearest neighbour from the current head position: a closed loop may start at any of its
// vertices (the nearest is taken), an open line at either end. A sequence (ExtrusionPath::sequence)
// is entered at its first path only and then printed in list order, each line from its end nearer
// to the head; a group whose paths have keep_order (monotonic ironing) is printed in its own order,
// only each path's start is chosen. TravelParams can move the first search's starting point and make
// distances follow the comb routes. How each travel goes and whether it retracts: planning/TravelRoute.h.
#include <optional>
#include <vector>

#include "planning/LayerPlan.h"
#include "planning/TravelRoute.h"
#include "toolpaths/core/ExtrusionPath.h"

namespace mixengine {

/// Appends the steps for `paths` (one group, printed together) to `steps`, starting from and
/// updating `head`; a ;TYPE: step is added whenever the feature differs from `feature`.
void appendOrderedPaths(std::vector<ExtrusionPath> paths, const TravelParams& params, Point2& head,
                        std::optional<Feature>& feature, std::vector<PlanStep>& steps);

/// The travel from `from` to `to` (planning/TravelRoute.h), retracting first when it must.
void appendTravelTo(const Point2& from, const Point2& to, const TravelParams& params,
                    std::vector<PlanStep>& steps);

/// The volume of a line: length × width × layer thickness × flow, in mm³.
double extrusionVolumeMm3(const Point2& from, const Point2& to, coord_um width_um, coord_um thickness_um,
                          double flow);

}  // namespace mixengine
