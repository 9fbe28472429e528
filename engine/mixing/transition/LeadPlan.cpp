#include "mixing/transition/LeadPlan.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>

#include "common/ParallelFor.h"
#include "mixing/transition/LeadCommands.h"
#include "mixing/transition/MixTable.h"
#include "mixing/transition/TowerVisits.h"

namespace mixengine {
namespace {

constexpr double kPurgePieceMm3 = 2.0;  ///< a purge is planned in pieces of this much, one command each
constexpr int kRungsPerChange = 8;      ///< the purge per layer is tried in eighths of a full change
constexpr int kTopRung = 16;            ///< … up to two full changes
constexpr double kGoal = 0.98;          ///< the visible share within the tolerance a purge aims for
constexpr int kIterations = 250;
/// A core cell's weight per mm³ against a visible one's: the core's mix is wished for, the visible
/// surface's is what counts
constexpr double kCoreWeight = 0.0005;
constexpr double kShellMargin = 0.0;  ///< a visible cell's margin in a print with a core

const MixVector& askedOf(const PrintPlan& plan, const StepTarget& t) {
    return plan.mixes[static_cast<std::size_t>(t.exact >= 0 ? t.exact : t.mix)];
}

/// Whether a layer's extrusions ask for more than one mix (or follow a field).
bool layerChanges(const std::vector<StepTarget>& targets) {
    int first = -1;
    for (const StepTarget& t : targets) {
        if (t.visible && t.exact >= 0)
            return true;
        if (t.mix >= 0 && first >= 0 && t.mix != first)
            return true;
        if (t.mix >= 0)
            first = t.mix;
    }
    return false;
}

/// A core (mixing_core_ratio) in a chamber: the chamber changes to the core's mix and back inside a layer
/// without touching the visible surface only where the layer's hidden extrusions hold two full changes
/// and more (`room_mm3`); elsewhere the core follows the shell.
struct CoreRule {
    bool any = false;
    double room_mm3 = 0;
};

double hiddenVolumeMm3(const std::vector<PlanStep>& steps, const std::vector<StepTarget>& targets) {
    double hidden = 0;
    for (std::size_t k = 0; k < steps.size(); ++k)
        if (steps[k].kind == PlanStep::Kind::Extrude && !targets[k].visible)
            hidden += steps[k].volume_mm3;
    return hidden;
}

/// How a layer's extrusions become cells.
struct CellRules {
    bool print_has_core = false;  ///< visible cells keep as close as they can (no margin)
    bool core_wished = false;     ///< this layer's core cells wish for the core's mix
};

/// An extrusion's cell: a visible one asks for its mix (the field's own where there is one), a core one
/// wishes for the core's where the layer allows; others are free.
FlowCell cellOf(const PrintPlan& plan, const PlanStep& step, const StepTarget& t, CellRules rules) {
    if (t.visible && (t.mix >= 0 || t.exact >= 0))
        return {step.volume_mm3, step.volume_mm3, askedOf(plan, t), rules.print_has_core ? kShellMargin : -1};
    if (t.core && t.mix >= 0 && rules.core_wished)
        return {step.volume_mm3, kCoreWeight * step.volume_mm3, askedOf(plan, t), 0};
    return {step.volume_mm3, 0, {}, -1};
}

/// The first guess: led by the visible cells alone (a core's wish would pull it off the surface).
std::vector<MixVector> guessOf(std::vector<FlowCell> cells, double lead_mm3, const MixVector& fallback) {
    for (FlowCell& cell : cells)
        if (cell.weight < 0.5 * cell.volume_mm3)
            cell.weight = 0;
    return leadingGuess(cells, lead_mm3, fallback);
}

bool anyCore(const std::vector<std::vector<StepTarget>>& targets) {
    for (const std::vector<StepTarget>& layer : targets)
        for (const StepTarget& t : layer)
            if (t.core)
                return true;
    return false;
}

/// Where a layer's sweep turns: before its last run of visible extrusions in one mix (the next layer
/// starts with that mix), after the extrusion before it; the first extrusion when none is visible.
std::size_t turnOf(const std::vector<PlanStep>& steps, const std::vector<StepTarget>& targets) {
    std::size_t first_extrusion = steps.size();
    int run_mix = -1;
    for (std::size_t k = steps.size(); k-- > 0;) {
        if (steps[k].kind != PlanStep::Kind::Extrude)
            continue;
        first_extrusion = k;
        const bool in_run = targets[k].visible && (run_mix < 0 || targets[k].mix == run_mix);
        if (!in_run && run_mix >= 0)
            return k + 1;
        if (in_run)
            run_mix = targets[k].mix;
    }
    return first_extrusion;
}

/// Where in a layer the purge goes: where its sweep turns (a field graded across the whole layer, whose
/// ends the chamber must reach), halfway through its change of mix (the change is at one place), or
/// spread over every change between the runs of its visible bands, each piece in proportion to the
/// step (a feathered edge between two wide regions: the purge lets the chamber sweep the edge's steps
/// with the visible lines between them).
enum class PurgeSite { Turn, MidChange, Spread };

/// A place for a purge (before step `at`) and the share of the layer's purge it takes.
struct PurgePlace {
    std::size_t at = 0;
    double share = 1.0;
};

/// Halfway through the layer's change: after the extrusion before the visible one at which the share
/// distance walked along its visible extrusions passes half its total (turnOf when it does not change).
std::size_t midChangeOf(const PrintPlan& plan, const std::vector<PlanStep>& steps,
                        const std::vector<StepTarget>& targets) {
    auto walk = [&](double stop_at) -> std::pair<double, std::size_t> {
        double walked = 0;
        const MixVector* before = nullptr;
        std::size_t after_previous = steps.size();
        for (std::size_t k = 0; k < steps.size(); ++k) {
            if (steps[k].kind != PlanStep::Kind::Extrude)
                continue;
            if (targets[k].visible && targets[k].mix >= 0) {
                const MixVector& asked = askedOf(plan, targets[k]);
                const double step = before ? shareDistance(asked, *before) : 0;
                if (before && walked + step >= stop_at)
                    return {walked, after_previous};
                walked += step;
                before = &asked;
            }
            after_previous = k + 1;
        }
        return {walked, steps.size()};
    };
    const double total = walk(1e300).first;
    return total > 1e-9 ? walk(total / 2).second : turnOf(steps, targets);
}

/// Spread: before each visible extrusion whose band differs from the visible one before it, after the
/// extrusion before it, in proportion to the difference (the turn alone when the layer does not change).
std::vector<PurgePlace> spreadOf(const PrintPlan& plan, const std::vector<PlanStep>& steps,
                                 const std::vector<StepTarget>& targets) {
    std::vector<PurgePlace> places;
    double total = 0;
    int before = -1;
    std::size_t after_previous = steps.size();
    for (std::size_t k = 0; k < steps.size(); ++k) {
        if (steps[k].kind != PlanStep::Kind::Extrude)
            continue;
        if (targets[k].visible && targets[k].mix >= 0) {
            const double step = before < 0
                                    ? 0
                                    : shareDistance(plan.mixes[static_cast<std::size_t>(targets[k].mix)],
                                                    plan.mixes[static_cast<std::size_t>(before)]);
            if (step > 0) {
                places.push_back({after_previous, step});
                total += step;
            }
            before = targets[k].mix;
        }
        after_previous = k + 1;
    }
    if (total <= 0)
        return {{turnOf(steps, targets), 1.0}};
    for (PurgePlace& place : places)
        place.share /= total;
    return places;
}

std::vector<PurgePlace> placesOf(const PrintPlan& plan, const std::vector<PlanStep>& steps,
                                 const std::vector<StepTarget>& targets, PurgeSite site) {
    if (site == PurgeSite::Spread)
        return spreadOf(plan, steps, targets);
    return {{site == PurgeSite::Turn ? turnOf(steps, targets) : midChangeOf(plan, steps, targets), 1.0}};
}

/// The cells of a layer's extrusions, with `purge_mm3` of purge in pieces at its places.
void appendLayer(const PrintPlan& plan, std::size_t l, const std::vector<StepTarget>& targets,
                 double purge_mm3, const CoreRule& core, PurgeSite site, std::vector<FlowCell>& cells) {
    const std::vector<PlanStep>& steps = plan.layers[l].steps;
    const CellRules rules{core.any, core.any && hiddenVolumeMm3(steps, targets) >= core.room_mm3};
    const std::vector<PurgePlace> places =
        purge_mm3 > 0 ? placesOf(plan, steps, targets, site) : std::vector<PurgePlace>{};
    std::size_t next = 0;
    for (std::size_t k = 0; k < steps.size(); ++k) {
        for (; next < places.size() && places[next].at == k; ++next)
            for (double left = purge_mm3 * places[next].share; left > 1e-9; left -= kPurgePieceMm3)
                cells.push_back({std::min(left, kPurgePieceMm3), 0, {}});
        if (steps[k].kind != PlanStep::Kind::Extrude)
            continue;
        cells.push_back(cellOf(plan, steps[k], targets[k], rules));
    }
}

/// The chamber before the first cell: as earlier groups left it, or full of the first asked mix.
std::vector<MixVector> startingTanks(const PrintPlan& plan,
                                     const std::vector<std::vector<StepTarget>>& targets,
                                     const TransitionSettings& settings) {
    if (settings.incoming)
        return settings.incoming->tanks();
    for (std::size_t l = 0; l < plan.layers.size(); ++l)
        for (std::size_t k = 0; k < targets[l].size(); ++k)
            if (plan.layers[l].steps[k].kind == PlanStep::Kind::Extrude && targets[l][k].mix >= 0)
                return std::vector<MixVector>(static_cast<std::size_t>(std::max(1, settings.chamber.stages)),
                                              askedOf(plan, targets[l][k]));
    return {};
}

/// The share of the asked volume whose outlet is within `tolerance`, for each of `tolerances`.
std::array<double, 2> withinShares(const std::vector<FlowCell>& cells, const std::vector<MixVector>& outlets,
                                   double tolerance) {
    double asked = 0, within = 0, loose = 0;
    for (std::size_t k = 0; k < cells.size(); ++k) {
        if (cells[k].weight <= 0)
            continue;
        const double off = shareDistance(outlets[k], cells[k].asked);
        asked += cells[k].weight;
        within += off <= tolerance ? cells[k].weight : 0;
        loose += off <= 2 * tolerance ? cells[k].weight : 0;
    }
    return asked > 0 ? std::array<double, 2>{within / asked, loose / asked} : std::array<double, 2>{1, 1};
}

/// The plan's facts the ladder is tried on.
struct Sweep {
    const PrintPlan& plan;
    const std::vector<std::vector<StepTarget>>& targets;
    const TransitionSettings& settings;
    std::vector<MixVector> tanks;
    std::vector<bool> purges;  ///< per layer: a tower visit (up to the last layer that changes)
    double full_change_mm3 = 0;
    double usual_thickness_mm = 0.1;
    CoreRule core;  ///< some hidden extrusion wishes for a core mix
    PurgeSite site = PurgeSite::Turn;

    std::vector<double> purgePerLayer(double changes) const {
        std::vector<double> out(plan.layers.size(), 0.0);
        for (std::size_t l = 0; l < out.size(); ++l)
            if (purges[l])
                out[l] = changes * full_change_mm3 * micronsToMm(thicknessOf(plan, l)) / usual_thickness_mm;
        return out;
    }
    std::array<double, 2> tryPurge(const std::vector<double>& purge) const {
        std::vector<FlowCell> cells;
        for (std::size_t l = 0; l < plan.layers.size(); ++l)
            appendLayer(plan, l, targets[l], purge[l], core, site, cells);
        const LeadSettings lead{settings.chamber, settings.tolerance / 2, kIterations};
        const std::vector<MixVector> commands =
            leadCommands(cells, tanks, guessOf(cells, settings.chamber.volume_mm3, tanks.front()), lead);
        return withinShares(cells, outletsOf(cells, tanks, commands, settings.chamber), settings.tolerance);
    }
};

Sweep sweepOf(const PrintPlan& plan, const std::vector<std::vector<StepTarget>>& targets,
              const TransitionSettings& settings, double full_change_mm3) {
    Sweep sweep{plan, targets,         settings, startingTanks(plan, targets, settings),
                {},   full_change_mm3, 0.1,      {anyCore(targets), 2 * full_change_mm3}};
    sweep.purges.assign(plan.layers.size(), false);
    std::vector<double> thickness_mm;
    for (std::size_t l = plan.layers.size(); l-- > 0;) {
        const bool changes = layerChanges(targets[l]);
        sweep.purges[l] = changes || (l + 1 < plan.layers.size() && sweep.purges[l + 1]);
        if (changes)
            thickness_mm.push_back(micronsToMm(thicknessOf(plan, l)));
    }
    if (!thickness_mm.empty()) {
        std::nth_element(thickness_mm.begin(), thickness_mm.begin() + thickness_mm.size() / 2,
                         thickness_mm.end());
        sweep.usual_thickness_mm = std::max(0.01, thickness_mm[thickness_mm.size() / 2]);
    }
    return sweep;
}

/// The site that leaves the most of the visible surface within the tolerance at one full change a layer.
struct SiteChoice {
    PurgeSite site = PurgeSite::Turn;
    std::array<double, 2> at_none{}, at_one{};  ///< the shares with no purge and one full change a layer
};

SiteChoice chooseSite(const Sweep& sweep, int threads) {
    constexpr std::array<PurgeSite, 3> kSites = {PurgeSite::Turn, PurgeSite::MidChange, PurgeSite::Spread};
    std::array<std::array<double, 2>, kSites.size() + 1> shares{};  // the last: no purge (any site)
    parallelFor(shares.size(), threads, [&](std::size_t i) {
        Sweep trial = sweep;
        trial.site = kSites[std::min(i, kSites.size() - 1)];
        shares[i] = trial.tryPurge(trial.purgePerLayer(i < kSites.size() ? 1.0 : 0.0));
    });
    std::size_t best = 0;
    for (std::size_t i = 1; i < kSites.size(); ++i)
        best = shares[i][0] > shares[best][0] + 1e-9 ? i : best;
    return {kSites[best], shares.back(), shares[best]};
}

/// The shares within the tolerance and twice it at each rung tried (rung r: r / kRungsPerChange full
/// changes per layer), each tried once.
class Ladder {
  public:
    explicit Ladder(const Sweep& sweep) : sweep_(sweep) {}
    void seed(int rung, const std::array<double, 2>& shares) { tried_[rung] = shares; }
    const std::array<double, 2>& at(int rung) {
        auto [it, added] = tried_.emplace(rung, std::array<double, 2>{});
        if (added)
            it->second = sweep_.tryPurge(sweep_.purgePerLayer(static_cast<double>(rung) / kRungsPerChange));
        return it->second;
    }
    /// The lowest rung in [lo, hi] whose share `which` reaches `goal` (hi when none), by bisection — more
    /// purge never leaves less within the tolerance.
    int lowest(int lo, int hi, std::size_t which, double goal) {
        while (lo < hi) {
            const int mid = (lo + hi) / 2;
            (at(mid)[which] >= goal ? hi : lo) = mid + (at(mid)[which] >= goal ? 0 : 1);
        }
        return hi;
    }

  private:
    const Sweep& sweep_;
    std::map<int, std::array<double, 2>> tried_;
};

/// The purge per layer, in full changes, chosen for the tolerance and for twice it. The tolerance: the
/// least that leaves kGoal of the visible surface within it, or within 2 points of what two full changes
/// leave when that is less; twice the tolerance: the least that leaves as much within it.
std::array<double, 2> chooseRungs(const Sweep& sweep, const SiteChoice& choice) {
    Ladder ladder(sweep);
    ladder.seed(0, choice.at_none);
    ladder.seed(kRungsPerChange, choice.at_one);
    if (choice.at_none[0] >= kGoal)
        return {0, 0};
    const double goal = choice.at_one[0] >= kGoal ? kGoal : std::min(kGoal, ladder.at(kTopRung)[0] - 0.02);
    const int rung = ladder.lowest(0, kTopRung, 0, goal);
    const int loose = ladder.lowest(0, rung, 1, ladder.at(rung)[0]);
    return {static_cast<double>(rung) / kRungsPerChange, static_cast<double>(loose) / kRungsPerChange};
}

/// Layer l with visits of the whole tower square at the purge's places, each its share of the square.
void insertVisits(PrintPlan& plan, std::size_t l, LayerTower& tower, std::vector<StepTarget>& targets,
                  PurgeSite site, TransitionReport& report) {
    const std::vector<PlanStep> steps = std::move(plan.layers[l].steps);
    const std::vector<PurgePlace> places = placesOf(plan, steps, targets, site);
    const double square_mm3 = tower.cursor.volumeLeftMm3();
    std::vector<PlanStep> out;
    std::vector<StepTarget> out_targets;
    std::size_t next = 0;
    for (std::size_t k = 0; k <= steps.size(); ++k) {
        for (; next < places.size() && places[next].at == k; ++next) {
            const bool last = next + 1 == places.size();
            const std::size_t before = out.size();
            visitTower(tower, last ? tower.cursor.volumeLeftMm3() : square_mm3 * places[next].share, -1,
                       steps, k, out);
            for (std::size_t i = before; i < out.size(); ++i)
                report.purge_mm3 += out[i].kind == PlanStep::Kind::Extrude ? out[i].volume_mm3 : 0;
            out_targets.resize(out.size());
        }
        if (k < steps.size()) {
            out.push_back(steps[k]);
            out_targets.push_back(targets[k]);
        }
    }
    plan.layers[l].steps = std::move(out);
    targets = std::move(out_targets);
    plan.layers[l].layer_change_retract_step = -1;
}

/// One warning on a core in a chamber: in how many layers it can take its mix, and how much of it leaves
/// the nozzle within the tolerance of it (`outlets`: per extrusion, in print order).
void reportCore(const PrintPlan& plan, const std::vector<std::vector<StepTarget>>& targets,
                const Sweep& sweep, const std::vector<MixVector>& outlets, TransitionReport& report) {
    int layers = 0, fitting = 0;
    double core_mm3 = 0, within_mm3 = 0;
    std::size_t cell = 0;
    for (std::size_t l = 0; l < plan.layers.size(); ++l) {
        const std::vector<PlanStep>& steps = plan.layers[l].steps;
        bool any = false;
        for (std::size_t k = 0; k < steps.size(); ++k) {
            if (steps[k].kind != PlanStep::Kind::Extrude)
                continue;
            const StepTarget& t = targets[l][k];
            if (t.core && t.mix >= 0) {
                any = true;
                core_mm3 += steps[k].volume_mm3;
                const bool close =
                    shareDistance(outlets[cell], plan.mixes[static_cast<std::size_t>(t.mix)]) <=
                    sweep.settings.tolerance;
                within_mm3 += close ? steps[k].volume_mm3 : 0;
            }
            ++cell;
        }
        layers += any ? 1 : 0;
        fitting += any && hiddenVolumeMm3(steps, targets[l]) >= sweep.core.room_mm3 ? 1 : 0;
    }
    char text[400];
    std::snprintf(
        text, sizeof text,
        "mixing: mixing_core_ratio: the core can take its mix in %d of its %d layers (the others hide "
        "less than two full changes of the chamber, %.0f mm3, and their core follows the shell's "
        "colour); %.1f %% of the core leaves the nozzle within %.2f of its mix",
        fitting, layers, sweep.core.room_mm3, core_mm3 > 0 ? 100.0 * within_mm3 / core_mm3 : 0.0,
        sweep.settings.tolerance);
    report.warnings.push_back(text);
}

/// The commands over the print as it will be written, into every extrusion's PlanStep::mix.
void setCommands(PrintPlan& plan, const std::vector<std::vector<StepTarget>>& targets, const Sweep& sweep,
                 TransitionReport& report) {
    std::vector<FlowCell> cells;
    for (std::size_t l = 0; l < plan.layers.size(); ++l)
        appendLayer(plan, l, targets[l], 0, sweep.core, sweep.site, cells);
    const LeadSettings lead{sweep.settings.chamber, sweep.settings.tolerance / 2, 2 * kIterations};
    const std::vector<MixVector> commands = leadCommands(
        cells, sweep.tanks, guessOf(cells, sweep.settings.chamber.volume_mm3, sweep.tanks.front()), lead);
    if (sweep.core.any)
        reportCore(plan, targets, sweep, outletsOf(cells, sweep.tanks, commands, sweep.settings.chamber),
                   report);
    MixTable table(plan.mixes);
    std::size_t cell = 0;
    for (PlannedLayer& layer : plan.layers)
        for (PlanStep& step : layer.steps)
            if (step.kind == PlanStep::Kind::Extrude)
                step.mix = table.indexOf(roundedMix(commands[cell++]));
}

}  // namespace

bool needsLeading(const std::vector<std::vector<StepTarget>>& targets) {
    for (const std::vector<StepTarget>& layer : targets)
        for (const StepTarget& t : layer)
            if ((t.visible && t.exact >= 0) || t.core)
                return true;
    return false;
}

void planLeading(PrintPlan& plan, std::vector<std::vector<StepTarget>>& targets,
                 const TransitionSettings& settings, TransitionReport& report) {
    Sweep sweep = sweepOf(plan, targets, settings, report.full_change_mm3);
    if (sweep.tanks.empty())
        return;
    const SiteChoice choice = chooseSite(sweep, settings.threads);
    sweep.site = choice.site;
    const std::array<double, 2> rungs = chooseRungs(sweep, choice);
    const std::vector<double> needed = sweep.purgePerLayer(rungs[0]);
    for (std::size_t l = 0; l < needed.size(); ++l) {
        report.needed_mm3 += needed[l];
        const bool changes = layerChanges(targets[l]);
        report.changes += changes ? 1 : 0;
        report.layers_with_changes += changes ? 1 : 0;
    }
    for (double v : sweep.purgePerLayer(rungs[1]))
        report.looser_needed_mm3 += v;
    const std::optional<TowerPlan> tower = sizeTower(plan, needed, settings, report);
    if (tower)
        report.tower = tower->shape;
    else
        report.unpurged_mm3 = report.needed_mm3;
    for (std::size_t l = 0; l < plan.layers.size(); ++l)
        if (std::optional<LayerTower> here = layerTower(plan, l, tower, settings))
            insertVisits(plan, l, *here, targets[l], sweep.site, report);
    setCommands(plan, targets, sweep, report);
}

}  // namespace mixengine
