#include "mixing/TransitionPlan.h"

#include <algorithm>
#include <cmath>

#include "mixing/StepContext.h"

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

coord_um thicknessOf(const PrintPlan& plan, std::size_t l) {
    const PlannedLayer& layer = plan.layers[l];
    if (layer.thickness > 0)
        return layer.thickness;
    return l == 0 ? layer.z : layer.z - plan.layers[l - 1].z;
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

/// The print's rectangle, from its extrusions.
void printBounds(const PrintPlan& plan, TowerSite& site) {
    site.print_min = {INT64_MAX, INT64_MAX};
    site.print_max = {INT64_MIN, INT64_MIN};
    for (const PlannedLayer& layer : plan.layers)
        for (const PlanStep& step : layer.steps)
            if (step.kind == PlanStep::Kind::Extrude || step.kind == PlanStep::Kind::Travel) {
                site.print_min = {std::min(site.print_min.X, step.to.X),
                                  std::min(site.print_min.Y, step.to.Y)};
                site.print_max = {std::max(site.print_max.X, step.to.X),
                                  std::max(site.print_max.Y, step.to.Y)};
            }
}

/// One layer's tower visits.
struct LayerTower {
    TowerCursor cursor;
    PlanStep travel, extrude;
};

/// The steps of one tower visit that purges `volume_mm3` of `mix` before step `at`, and what brings
/// the print back to where it was.
void visitTower(LayerTower& tower, double volume_mm3, int mix, const std::vector<PlanStep>& steps,
                std::size_t at, std::vector<PlanStep>& out) {
    PlanStep mesh;
    mesh.kind = PlanStep::Kind::SetMesh;
    mesh.mesh_index = -1;
    PlanStep feature;
    feature.kind = PlanStep::Kind::SetFeature;
    feature.feature = Feature::PrimeTower;
    out.push_back(mesh);
    out.push_back(feature);
    tower.extrude.mix = mix;
    tower.cursor.emit(volume_mm3, tower.travel, tower.extrude, out);
    StepContext before;
    for (std::size_t k = 0; k < at; ++k)
        before.advance(steps[k]);
    before.resumeInto(tower.travel, out);
}

const PlanStep* firstTravel(const PlannedLayer& layer) {
    for (const PlanStep& s : layer.steps)
        if (s.kind == PlanStep::Kind::Travel)
            return &s;
    return nullptr;
}

struct TowerPlan {
    PurgeTowerShape shape;
    std::size_t last_layer = 0;
};

std::optional<TowerPlan> sizeTower(const PrintPlan& plan, const std::vector<double>& needed,
                                   TransitionSettings settings, TransitionReport& report) {
    double worst_mm2 = 0;  // purge volume per mm of layer height
    std::optional<std::size_t> last;
    for (std::size_t l = 0; l < needed.size(); ++l) {
        if (needed[l] <= 1e-6)
            continue;
        worst_mm2 = std::max(worst_mm2, needed[l] / micronsToMm(std::max<coord_um>(1, thicknessOf(plan, l))));
        last = l;
    }
    if (!last || !settings.tower)
        return std::nullopt;
    const coord_um w = settings.line_width_um;
    coord_um side = std::max<coord_um>(mmToMicrons(5.0), mmToMicrons(std::sqrt(worst_mm2)) + w);
    side = (side + w - 1) / w * w;
    printBounds(plan, settings.site);
    if (settings.keep_clear) {
        const auto& [lo, hi] = *settings.keep_clear;
        settings.site.print_min = {std::min(settings.site.print_min.X, lo.X),
                                   std::min(settings.site.print_min.Y, lo.Y)};
        settings.site.print_max = {std::max(settings.site.print_max.X, hi.X),
                                   std::max(settings.site.print_max.Y, hi.Y)};
    }
    const std::optional<Point2> corner = placeTower(settings.site, side);
    if (!corner) {
        report.warnings.push_back("mixing: no room on the build plate for a purge tower of " +
                                  std::to_string(side / 1000) +
                                  " mm beside the print; changes of mix are purged "
                                  "into hidden volume only");
        return std::nullopt;
    }
    return TowerPlan{{*corner, side, w}, *last};
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

std::optional<LayerTower> layerTower(const PrintPlan& plan, std::size_t l,
                                     const std::optional<TowerPlan>& tower,
                                     const TransitionSettings& settings) {
    const PlanStep* travel = firstTravel(plan.layers[l]);
    if (!tower || l > tower->last_layer || !travel)
        return std::nullopt;
    PlanStep extrude;
    extrude.kind = PlanStep::Kind::Extrude;
    extrude.feature = Feature::PrimeTower;
    extrude.speed_mm_s = settings.speed_at ? settings.speed_at(plan.layers[l].index) : settings.speed_mm_s;
    extrude.width_um = tower->shape.line_width_um;
    return LayerTower{TowerCursor(towerPath(tower->shape, plan.layers[l].index), tower->shape.line_width_um,
                                  thicknessOf(plan, l)),
                      *travel, extrude};
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
