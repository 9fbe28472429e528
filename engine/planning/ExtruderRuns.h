#pragma once
// A print cut into extruder runs: the steps one extruder prints without a switch, within one layer
// (CuraEngine's extruder plans). A run starts at a layer's start or just after a SetExtruder step
// and ends before the next SetExtruder step or at the layer's end; runs without a move are left out
// (a layer that starts with a switch has no run of the extruder it started with).
// Times are the planner's distance / speed estimates (planning/Cooling.h), after cooling.
#include <cstddef>
#include <vector>

#include "planning/LayerPlan.h"

namespace mixengine {

struct ExtruderRun {
    std::size_t layer = 0;  ///< index into PrintPlan::layers
    std::size_t begin = 0;  ///< first step of the run (after its SetExtruder step)
    std::size_t end = 0;    ///< one past the last step
    int extruder = 0;
    bool switched = false;     ///< a SetExtruder step (at begin − 1) starts the run
    double seconds = 0;        ///< every move
    double unretracted_s = 0;  ///< extrusions and travel while not retracted
    double volume_mm3 = 0;     ///< extruded
};

struct ExtruderRuns {
    std::vector<ExtruderRun> runs;
    std::vector<std::vector<double>> step_seconds;  ///< [layer][step], 0 for markers
};

/// The runs of `plan`, whose first layer starts with `start_extruder` active and the head at `start`.
ExtruderRuns extruderRuns(const PrintPlan& plan, int start_extruder, Point2 start);

}  // namespace mixengine
