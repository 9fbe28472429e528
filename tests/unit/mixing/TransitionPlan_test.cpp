// Transition planning (mixing/transition/LayerOrder.h, mixing/transition/TransitionPlan.h,
// mixing/transition/PurgeTower.h) on small hand-made plans: two regions per layer, A on the left and B on the
// right, each with a hidden fill line and a visible outer-wall line.
#include "mixing/transition/TransitionPlan.h"

#include <gtest/gtest.h>

namespace mixengine {
namespace {

PlanStep travel(coord_um x, coord_um y) {
    PlanStep s;
    s.kind = PlanStep::Kind::Travel;
    s.to = {x, y};
    s.speed_mm_s = 150;
    return s;
}

PlanStep extrude(coord_um x, coord_um y, double mm3) {
    PlanStep s;
    s.kind = PlanStep::Kind::Extrude;
    s.to = {x, y};
    s.volume_mm3 = mm3;
    s.speed_mm_s = 30;
    return s;
}

PlanStep feature(Feature f) {
    PlanStep s;
    s.kind = PlanStep::Kind::SetFeature;
    s.feature = f;
    return s;
}

struct Built {
    PrintPlan plan;
    std::vector<std::vector<StepTarget>> targets;
};

/// Per layer, in the planner's order: wall A (visible), wall B (visible), fill A, fill B (hidden).
Built twoRegions(int layers, double fill_mm3) {
    Built b;
    b.plan.mixes = {MixVector::only(0, 2), MixVector::only(1, 2)};
    for (int l = 0; l < layers; ++l) {
        PlannedLayer layer;
        layer.index = l;
        layer.z = 200 * (l + 1);
        layer.thickness = 200;
        std::vector<StepTarget> t;
        auto add = [&](PlanStep s, int mix, bool visible) {
            layer.steps.push_back(s);
            t.push_back(s.kind == PlanStep::Kind::Extrude ? StepTarget{mix, visible} : StepTarget{});
        };
        add(feature(Feature::WallOuter), -1, false);
        add(travel(0, 0), -1, false);
        add(extrude(10'000, 0, 2), 0, true);
        add(travel(20'000, 0), -1, false);
        add(extrude(30'000, 0, 2), 1, true);
        add(feature(Feature::Fill), -1, false);
        add(travel(0, 1000), -1, false);
        add(extrude(10'000, 1000, fill_mm3), 0, false);
        add(travel(20'000, 1000), -1, false);
        add(extrude(30'000, 1000, fill_mm3), 1, false);
        b.plan.layers.push_back(layer);
        b.targets.push_back(t);
    }
    return b;
}

/// The visible mixes of a layer in print order.
std::vector<int> visibleOrder(const PlannedLayer& layer, const std::vector<StepTarget>& targets) {
    std::vector<int> order;
    for (std::size_t i = 0; i < layer.steps.size(); ++i)
        if (targets[i].visible && (order.empty() || order.back() != targets[i].mix))
            order.push_back(targets[i].mix);
    return order;
}

TransitionSettings settings() {
    TransitionSettings s;
    s.chamber = {40, 3};
    s.tolerance = 0.1;
    s.site.plate_max = {200'000, 200'000};
    s.site.preferred_anchor = Point2{190'000, 10'000};
    return s;
}

TEST(MixingTransitionPlan, OrdersEachLayerByMixAlternatingLayerByLayer) {
    Built b = twoRegions(4, 1);
    planTransitions(b.plan, b.targets, settings());
    EXPECT_EQ(visibleOrder(b.plan.layers[0], b.targets[0]), (std::vector<int>{0, 1}));
    EXPECT_EQ(visibleOrder(b.plan.layers[1], b.targets[1]), (std::vector<int>{1, 0}));
    EXPECT_EQ(visibleOrder(b.plan.layers[2], b.targets[2]), (std::vector<int>{0, 1}));
}

TEST(MixingTransitionPlan, EveryVisibleExtrusionLeavesWithinTheTolerance) {
    Built b = twoRegions(6, 1);
    const TransitionReport report = planTransitions(b.plan, b.targets, settings());
    Chamber chamber({40, 3}, MixVector::only(0, 2));
    bool first = true;
    for (std::size_t l = 0; l < b.plan.layers.size(); ++l)
        for (std::size_t i = 0; i < b.plan.layers[l].steps.size(); ++i) {
            const PlanStep& s = b.plan.layers[l].steps[i];
            if (s.kind != PlanStep::Kind::Extrude)
                continue;
            const MixVector& commanded = b.plan.mixes[static_cast<std::size_t>(s.mix)];
            if (first)
                chamber = Chamber({40, 3}, commanded), first = false;
            const MixVector before = chamber.outlet();
            chamber.push(commanded, s.volume_mm3);
            if (b.targets[l][i].visible) {
                const MixVector& asked = b.plan.mixes[static_cast<std::size_t>(b.targets[l][i].mix)];
                EXPECT_LE(shareDistance(before, asked), 0.1 + 1e-3) << "layer " << l << " step " << i;
                EXPECT_LE(shareDistance(chamber.outlet(), asked), 0.1 + 1e-3)
                    << "layer " << l << " step " << i;
            }
        }
    // one change per layer after the first mix; each about a full change less the hidden fill absorbed
    EXPECT_EQ(report.changes, 6);
    EXPECT_GT(report.purge_mm3, 6 * (70.96 - 2 - 2) - 1);
    EXPECT_LT(report.purge_mm3, 6 * 70.96 * 1.25);
    ASSERT_TRUE(report.tower);
}

TEST(MixingTransitionPlan, HiddenVolumeAbsorbsTheChangeBeforeTheTower) {
    Built big = twoRegions(3, 60);  // fill of 60 mm³ per region: most of a change
    const TransitionReport report = planTransitions(big.plan, big.targets, settings());
    EXPECT_LT(report.needed_mm3, 3 * 70.96 - 3 * 60 + 3);
    Built none = twoRegions(3, 200);  // more hidden volume than a change needs
    EXPECT_EQ(planTransitions(none.plan, none.targets, settings()).purge_mm3, 0);
}

TEST(MixingTransitionPlan, WithoutATowerTheUnpurgedVolumeIsReported) {
    Built b = twoRegions(2, 1);
    TransitionSettings s = settings();
    s.tower = false;
    const TransitionReport report = planTransitions(b.plan, b.targets, s);
    EXPECT_EQ(report.purge_mm3, 0);
    EXPECT_GT(report.unpurged_mm3, 2 * 60.0);
}

TEST(MixingTransitionPlan, TheTowerPrintsAtItsLayersSpeed) {
    Built b = twoRegions(3, 1);
    TransitionSettings s = settings();
    s.speed_at = [](int layer) { return layer == 0 ? 20.0 : 55.0; };
    planTransitions(b.plan, b.targets, s);
    for (const PlannedLayer& layer : b.plan.layers) {
        Feature feature = Feature::Fill;
        int tower_moves = 0;
        for (const PlanStep& step : layer.steps) {
            if (step.kind == PlanStep::Kind::SetFeature)
                feature = step.feature;
            if (step.kind == PlanStep::Kind::Extrude && feature == Feature::PrimeTower) {
                EXPECT_EQ(step.speed_mm_s, layer.index == 0 ? 20.0 : 55.0) << layer.index;
                ++tower_moves;
            }
        }
        EXPECT_GT(tower_moves, 0) << layer.index;
    }
}

TEST(MixingPurgeTower, StandsClearOfThePrintOnThePlate) {
    TowerSite site;
    site.plate_max = {100'000, 100'000};
    site.print_min = {40'000, 40'000};
    site.print_max = {60'000, 60'000};
    site.preferred_anchor = Point2{55'000, 45'000};  // on the print: not used
    const std::optional<Point2> corner = placeTower(site, 20'000);
    ASSERT_TRUE(corner);
    EXPECT_GT(corner->X, 63'000);  // right of the print, with the clearance
    site.print_max = {99'000, 99'000};
    site.print_min = {1'000, 1'000};
    EXPECT_FALSE(placeTower(site, 20'000));
}

TEST(MixingPurgeTower, HandsOutItsSquareByVolume) {
    const PurgeTowerShape shape{{0, 0}, 10'000, 500};
    TowerCursor cursor(towerPath(shape, 0), 500, 200);
    // 20 lines of 9.5 mm plus 19 connectors of 0.5 mm, 0.5 × 0.2 mm²
    EXPECT_NEAR(cursor.volumeLeftMm3(), (20 * 9.5 + 19 * 0.5) * 0.1, 1e-6);
    std::vector<PlanStep> steps;
    cursor.emit(5.0, travel(0, 0), extrude(0, 0, 0), steps);
    double sum = 0;
    for (const PlanStep& s : steps)
        sum += s.kind == PlanStep::Kind::Extrude ? s.volume_mm3 : 0;
    EXPECT_NEAR(sum, 5.0, 1e-9);
    EXPECT_NEAR(cursor.volumeLeftMm3(), 19.95 - 5.0, 1e-6);
}

}  // namespace
}  // namespace mixengine
