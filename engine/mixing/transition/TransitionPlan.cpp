#include "mixing/transition/TransitionPlan.h"

#include <algorithm>
#include <cmath>

#include "mixing/transition/LeadPlan.h"
#include "mixing/transition/TowerVisits.h"

namespace mixengine {
namespace {

/// The commanded mix of every step of a layer (−1 for steps that do not extrude).
std::vector<int> commandsOf(const PlannedLayer& layer, const std::vector<StepTarget>& targets) {
    std::vector<int> commands(layer.steps.size(), -1);
    int next_visible = -1;
    for (std::size_t k = layer.steps.size(); k-- > 0;) {
        if (layer.steps[k].kind == PlanStep::Kind::Extrude && targets[k].visible)
            next_visible = targets[k].mix;
        commands[k] = layer.steps[k].kind == PlanStep::Kind::Extrude ? next_visible : -1;
    }
    int last_visible = -1;
    for (std::size_t k = 0; k < layer.steps.size(); ++k) {
        if (layer.steps[k].kind != PlanStep::Kind::Extrude)
            continue;
        if (targets[k].visible)
            last_visible = targets[k].mix;
        if (commands[k] < 0)
            commands[k] = last_visible >= 0 ? last_visible : targets[k].mix;
    }
    return commands;
}

/// Where a purge may go: the step after the extrusion before each run of visible extrusions.
std::vector<std::size_t> purgePoints(const PlannedLayer& layer, const std::vector<StepTarget>& targets) {
    std::vector<std::size_t> points;
    std::size_t after_previous = 0;
    bool in_visible_run = false;
    int run_mix = -1;
    for (std::size_t k = 0; k < layer.steps.size(); ++k) {
        if (layer.steps[k].kind != PlanStep::Kind::Extrude)
            continue;
        const bool starts = targets[k].visible && (!in_visible_run || targets[k].mix != run_mix);
        if (starts)
            points.push_back(after_previous);
        in_visible_run = targets[k].visible;
        run_mix = targets[k].mix;
        after_previous = k + 1;
    }
    return points;
}

/// Per layer, the volume the changes need beyond what flows through the chamber anyway (the layers as
/// ordered, commands as commandsOf); the chamber pushed as if each purge happened where it is needed.
std::vector<double> neededPerLayer(const PrintPlan& plan, const std::vector<std::vector<StepTarget>>& targets,
                                   const ChamberSpec& spec, double tolerance,
                                   const std::optional<Chamber>& incoming) {
    std::vector<double> needed(plan.layers.size(), 0.0);
    std::optional<Chamber> chamber = incoming;
    for (std::size_t l = 0; l < plan.layers.size(); ++l) {
        const PlannedLayer& layer = plan.layers[l];
        const std::vector<int> commands = commandsOf(layer, targets[l]);
        const std::vector<std::size_t> points = purgePoints(layer, targets[l]);
        std::size_t next_point = 0;
        for (std::size_t k = 0; k < layer.steps.size(); ++k) {
            if (commands[k] < 0)
                continue;
            const MixVector& mix = plan.mixes[static_cast<std::size_t>(commands[k])];
            if (!chamber)
                chamber.emplace(spec, mix);
            while (next_point < points.size() && points[next_point] <= k) {
                const double need = chamber->volumeToReach(mix, tolerance);
                chamber->push(mix, need);
                needed[l] += need;
                ++next_point;
            }
            chamber->push(mix, layer.steps[k].volume_mm3);
        }
    }
    return needed;
}

/// The steps being written for one layer in pass 2, with the chamber they flow through.
struct LayerWriter {
    const PrintPlan& plan;
    const TransitionSettings& settings;
    std::optional<Chamber>& chamber;
    TransitionReport& report;
    std::vector<PlanStep> out;
    std::vector<StepTarget> targets;

    const MixVector& mixOf(int index) const { return plan.mixes[static_cast<std::size_t>(index)]; }
    void push(const PlanStep& step, const StepTarget& target) {
        if (step.kind == PlanStep::Kind::Extrude) {
            if (!chamber)
                chamber.emplace(settings.chamber, mixOf(step.mix));
            chamber->push(mixOf(step.mix), step.volume_mm3);
        }
        out.push_back(step);
        targets.push_back(target);
    }
    void pushVisit(const std::vector<PlanStep>& visit) {
        for (const PlanStep& s : visit) {
            if (s.kind == PlanStep::Kind::Extrude)
                report.purge_mm3 += s.volume_mm3;
            push(s, StepTarget{});
        }
    }
};

/// Before step `at` (a run of visible extrusions in `mix` follows): purge what the chamber needs.
/// Returns whether the chamber needed a change.
bool purgeAt(LayerWriter& w, std::optional<LayerTower>& tower, const std::vector<PlanStep>& steps,
             std::size_t at, int mix) {
    const MixVector& m = w.mixOf(mix);
    if (!w.chamber)
        w.chamber.emplace(w.settings.chamber, m);
    double need = w.chamber->volumeToReach(m, w.settings.tolerance);
    if (need <= 0)
        return false;
    ++w.report.changes;
    if (tower) {
        std::vector<PlanStep> visit;
        visitTower(*tower, need, mix, steps, at, visit);
        w.pushVisit(visit);
        need = w.chamber->volumeToReach(m, w.settings.tolerance);
    }
    w.report.unpurged_mm3 += need;
    return true;
}

/// The first commanded mix at or after step `k`.
int nextCommand(const std::vector<int>& commands, std::size_t k) {
    for (std::size_t j = k; j < commands.size(); ++j)
        if (commands[j] >= 0)
            return commands[j];
    return -1;
}

/// The last commanded mix of a layer (−1: none).
int lastCommand(const std::vector<int>& commands) {
    for (std::size_t j = commands.size(); j-- > 0;)
        if (commands[j] >= 0)
            return commands[j];
    return -1;
}

/// Pass 2 on one layer: the tower visits inserted, the commands set, the chamber pushed. What is left
/// of the tower's square is printed at the layer's end in the mix the layer ends with (so the tower
/// stands; the next layer starts in that mix).
void planLayer(PrintPlan& plan, std::size_t l, std::vector<StepTarget>& targets,
               const std::optional<TowerPlan>& tower, const TransitionSettings& settings,
               std::optional<Chamber>& chamber, TransitionReport& report) {
    const PlannedLayer& layer = plan.layers[l];
    const std::vector<int> commands = commandsOf(layer, targets);
    const std::vector<std::size_t> points = purgePoints(layer, targets);
    std::optional<LayerTower> here = layerTower(plan, l, tower, settings);
    LayerWriter w{plan, settings, chamber, report, {}, {}};
    std::size_t next_point = 0;
    bool changed = false;
    for (std::size_t k = 0; k < layer.steps.size(); ++k) {
        for (; next_point < points.size() && points[next_point] == k; ++next_point)
            changed = purgeAt(w, here, layer.steps, k, nextCommand(commands, k)) || changed;
        PlanStep step = layer.steps[k];
        if (step.kind == PlanStep::Kind::Extrude)
            step.mix = commands[k];
        w.push(step, targets[k]);
    }
    const int last = lastCommand(commands);
    if (here && here->cursor.volumeLeftMm3() > 1e-6 && last >= 0) {
        std::vector<PlanStep> visit;
        visitTower(*here, here->cursor.volumeLeftMm3(), last, w.out, w.out.size(), visit);
        w.pushVisit(visit);
    }
    report.layers_with_changes += changed ? 1 : 0;
    plan.layers[l].steps = std::move(w.out);
    targets = std::move(w.targets);
}

}  // namespace

TransitionReport planTransitions(PrintPlan& plan, std::vector<std::vector<StepTarget>>& targets,
                                 const TransitionSettings& settings) {
    TransitionReport report;
    report.full_change_mm3 = fullChangeVolumeMm3(settings.chamber, settings.tolerance);
    int last_mix = -1;
    for (std::size_t l = 0; l < plan.layers.size(); ++l) {
        OrderedLayer ordered = orderByMix(plan.layers[l], targets[l], last_mix, plan.mixes);
        plan.layers[l].steps = std::move(ordered.steps);
        targets[l] = std::move(ordered.targets);
        if (ordered.reordered)
            plan.layers[l].layer_change_retract_step = -1;
        for (const StepTarget& t : targets[l])
            if (t.visible)
                last_mix = t.mix;
    }
    if (needsLeading(targets)) {  // a continuous field: lead the chamber (mixing/transition/LeadPlan.h)
        planLeading(plan, targets, settings, report);
        return report;
    }
    const std::vector<double> needed =
        neededPerLayer(plan, targets, settings.chamber, settings.tolerance, settings.incoming);
    for (double v : needed)
        report.needed_mm3 += v;
    for (double v :
         neededPerLayer(plan, targets, settings.chamber, 2 * settings.tolerance, settings.incoming))
        report.looser_needed_mm3 += v;
    const std::optional<TowerPlan> tower = sizeTower(plan, needed, settings, report);
    if (tower)
        report.tower = tower->shape;
    std::optional<Chamber> chamber = settings.incoming;
    for (std::size_t l = 0; l < plan.layers.size(); ++l)
        planLayer(plan, l, targets[l], tower, settings, chamber, report);
    return report;
}

}  // namespace mixengine
