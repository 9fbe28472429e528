#include "planning/ExtruderRuns.h"

#include "planning/Cooling.h"

namespace mixengine {
namespace {

bool isMove(const PlanStep& step) {
    return step.kind == PlanStep::Kind::Travel || step.kind == PlanStep::Kind::Extrude;
}

/// Adds the times and volume of the run's steps; keeps the run when it has a move.
void closeRun(ExtruderRun run, const std::vector<PlanStep>& steps, const std::vector<double>& seconds,
              bool& retracted, std::vector<ExtruderRun>& out) {
    bool moves = false;
    for (std::size_t i = run.begin; i < run.end; ++i) {
        const PlanStep& step = steps[i];
        if (!isMove(step))
            continue;
        moves = true;
        if (step.kind == PlanStep::Kind::Extrude) {
            retracted = false;
            run.volume_mm3 += step.volume_mm3;
        } else if (step.retract) {
            retracted = true;
        }
        run.seconds += seconds[i];
        if (!retracted)
            run.unretracted_s += seconds[i];
    }
    if (moves)
        out.push_back(run);
}

Point2 lastPosition(const PlannedLayer& layer, Point2 start) {
    for (auto it = layer.steps.rbegin(); it != layer.steps.rend(); ++it) {
        if (isMove(*it))
            return it->to;
    }
    return start;
}

}  // namespace

ExtruderRuns extruderRuns(const PrintPlan& plan, int start_extruder, Point2 start) {
    ExtruderRuns out;
    int extruder = start_extruder;
    bool retracted = false;
    for (std::size_t l = 0; l < plan.layers.size(); ++l) {
        const std::vector<PlanStep>& steps = plan.layers[l].steps;
        out.step_seconds.push_back(stepSeconds(plan.layers[l], start));
        ExtruderRun run{l, 0, 0, extruder};
        for (std::size_t i = 0; i < steps.size(); ++i) {
            if (steps[i].kind != PlanStep::Kind::SetExtruder)
                continue;
            run.end = i;
            closeRun(run, steps, out.step_seconds.back(), retracted, out.runs);
            extruder = steps[i].extruder;
            retracted = true;  // a switch retracts the filament it leaves (gcode/GCodeExport.h)
            run = ExtruderRun{l, i + 1, 0, extruder, true};
        }
        run.end = steps.size();
        closeRun(run, steps, out.step_seconds.back(), retracted, out.runs);
        start = lastPosition(plan.layers[l], start);
    }
    return out;
}

}  // namespace mixengine
