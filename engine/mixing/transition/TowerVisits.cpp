#include "mixing/transition/TowerVisits.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "mixing/transition/StepContext.h"

namespace mixengine {
namespace {

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

const PlanStep* firstTravel(const PlannedLayer& layer) {
    for (const PlanStep& s : layer.steps)
        if (s.kind == PlanStep::Kind::Travel)
            return &s;
    return nullptr;
}

}  // namespace

coord_um thicknessOf(const PrintPlan& plan, std::size_t l) {
    const PlannedLayer& layer = plan.layers[l];
    if (layer.thickness > 0)
        return layer.thickness;
    return l == 0 ? layer.z : layer.z - plan.layers[l - 1].z;
}

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

}  // namespace mixengine
