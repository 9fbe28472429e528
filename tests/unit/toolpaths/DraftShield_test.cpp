// Draft shield (toolpaths/adhesion/DraftShield.h): its outline, layers and style, and the skirt around it.
#include "toolpaths/adhesion/DraftShield.h"

#include <gtest/gtest.h>

#include "ToolpathTestSupport.h"
#include "geometry/PointQueries.h"
#include "geometry/PolygonOps.h"
#include "toolpaths/adhesion/Adhesion.h"
#include "toolpaths/support/Support.h"

namespace mixengine {
namespace {

using test::rect;

struct Print {
    ResolvedMachine machine;
    std::vector<Paths> model;
    std::vector<std::set<int>> used;

    /// A 20 × 10 mm block, `layers` layers of fdmprinter's 0.1 mm (first 0.3 mm).
    Print(const SettingValues& values, int layers)
        : machine(test::fdmMachine(values)),
          model(static_cast<std::size_t>(layers), Paths{rect(0, 0, 20'000, 10'000)}),
          used(static_cast<std::size_t>(layers), std::set<int>{0}) {}

    DraftShieldResult shield(std::size_t first = 0) const {
        return generateDraftShield({&machine.global, &machine.extruders, &model, nullptr, &used, first});
    }
};

int layersWithShield(const DraftShieldResult& r) {
    int n = 0;
    for (const auto& layer : r.layers)
        n += layer.empty() ? 0 : 1;
    return n;
}

TEST(DraftShield, NoneUnlessEnabled) {
    const Print print({}, 30);
    const DraftShieldResult r = print.shield();
    EXPECT_TRUE(r.outline.empty());
    EXPECT_EQ(layersWithShield(r), 0);
}

TEST(DraftShield, OneLoopAtTheDistanceOnEveryLayer) {
    const Print print(
        {{"draft_shield_enabled", "True"}, {"draft_shield_dist", "5"}, {"adhesion_type", "skirt"}}, 30);
    const DraftShieldResult r = print.shield();
    ASSERT_EQ(r.outline.size(), 1u);
    const ClipperLib::IntRect b = boundsOf(r.outline);
    // Within the round joins' polygons (10 µm arcs of 100 mm, then simplified by 25 µm).
    EXPECT_NEAR(double(b.left), -5'000, 60);
    EXPECT_NEAR(double(b.right), 25'000, 60);
    EXPECT_NEAR(double(b.top), -5'000, 60);
    EXPECT_NEAR(double(b.bottom), 15'000, 60);
    // The block grown by 5 mm with round corners: 20 × 10 + 2 · 5 · 30 + π · 25 mm².
    EXPECT_NEAR(areaUm2(r.outline) / 1e6, 200 + 300 + 3.14159 * 25, 5.0);
    EXPECT_EQ(layersWithShield(r), 30);
    const ExtrusionPath& loop = r.layers[12].front();
    EXPECT_EQ(loop.feature, Feature::DraftShield);
    EXPECT_EQ(featureMarker(loop.feature), "SKIRT");
    EXPECT_TRUE(loop.closed);
    EXPECT_EQ(loop.width_um, 400);  // skirt_brim_line_width
    EXPECT_EQ(loop.speed_mm_s, print.machine.global.velocityMmPerS(key::skirt_brim_speed));
}

TEST(DraftShield, LimitedHeightStopsOneLayerAboveTheHeight) {
    // (1.0 − 0.3) / 0.1 + 1 = 8: layers 0 … 8, as CuraEngine.
    const Print print({{"draft_shield_enabled", "True"},
                       {"draft_shield_height_limitation", "limited"},
                       {"draft_shield_height", "1.0"},
                       {"adhesion_type", "none"}},
                      30);
    const DraftShieldResult r = print.shield();
    EXPECT_EQ(layersWithShield(r), 9);
    EXPECT_FALSE(r.layers[8].empty());
    EXPECT_TRUE(r.layers[9].empty());
    const DraftShieldResult lifted = print.shield(2);  // two empty layers dropped below: counted from 2
    EXPECT_TRUE(lifted.layers[1].empty());
    EXPECT_FALSE(lifted.layers[10].empty());
    EXPECT_TRUE(lifted.layers[11].empty());
}

TEST(DraftShield, WithABrimTheFirstLayerHasNoShieldButTheBrimFillsItsFoot) {
    const Print print({{"draft_shield_enabled", "True"}, {"adhesion_type", "brim"}}, 10);
    const DraftShieldResult r = print.shield();
    EXPECT_TRUE(r.layers[0].empty());
    EXPECT_FALSE(r.layers[1].empty());
    const AdhesionResult without =
        generateAdhesion({&print.machine.global, &print.machine.extruders, print.model[0], {}, {}});
    const AdhesionResult with =
        generateAdhesion({&print.machine.global, &print.machine.extruders, print.model[0], {}, r.outline});
    EXPECT_GT(with.paths.size(), without.paths.size());
    // The foot's loops lie inside the shield's outline (5 µm: growing its many nearly straight vertices,
    // kept as CuraEngine keeps them, by less rounds some edges in).
    for (std::size_t i = without.paths.size(); i < with.paths.size(); ++i)
        EXPECT_TRUE(differenceOf({with.paths[i].points}, offsetPolygons(r.outline, 5)).empty()) << i;
}

TEST(DraftShield, TheSkirtGoesAroundTheShield) {
    const Print print(
        {{"draft_shield_enabled", "True"}, {"adhesion_type", "skirt"}, {"draft_shield_dist", "10"}}, 10);
    const DraftShieldResult r = print.shield();
    const AdhesionResult skirt =
        generateAdhesion({&print.machine.global, &print.machine.extruders, print.model[0], {}, r.outline});
    ASSERT_FALSE(skirt.paths.empty());
    // Innermost skirt loop (last) one line width outside the shield.
    const ClipperLib::IntRect inner = boundsOf({skirt.paths.back().points});
    EXPECT_NEAR(double(inner.left), -10'000 - 400, 40);
    EXPECT_NEAR(double(inner.right), 30'000 + 400, 40);
}

TEST(DraftShield, ApproximateConvexHullClosesConcavities) {
    const Paths l_shape{{{0, 0}, {20'000, 0}, {20'000, 5'000}, {5'000, 5'000}, {5'000, 20'000}, {0, 20'000}}};
    const Paths hull = approxConvexHull(l_shape, 0);
    // The triangle between the arms filled up to a 100 mm arc over its 21.2 mm side: 175 + 112.5 −
    // 100² / 2 · (θ − sin θ) mm², θ = 2 asin(21.2 / 200), a segment of 8.0 mm².
    EXPECT_NEAR(areaUm2(hull) / 1e6, 175 + 112.5 - 8.0, 0.5);
}

}  // namespace
}  // namespace mixengine

namespace mixengine {
namespace {

TEST(BrimReplacesSupport, TheBrimsWidthAroundTheModelHasNoSupportOnLayerZero) {
    // A 10 mm ring (a 4 mm hole): 20 brim lines of 0.4 mm cover 8 mm around its outside only.
    const Paths ring = {test::rect(0, 0, 10'000, 10'000), test::rect(7'000, 3'000, 3'000, 7'000)};
    const ResolvedMachine brim = test::fdmMachine({{"adhesion_type", "brim"}, {"brim_line_count", "20"}});
    const Paths covered = brimCoveredArea(brim.global, &brim.extruders, ring);
    EXPECT_EQ(boundsOf(covered).left, -8'000);
    EXPECT_EQ(boundsOf(covered).right, 18'000);
    EXPECT_FALSE(insideArea(covered, {5'000, 5'000}, false));  // the hole keeps its support
    EXPECT_TRUE(insideArea(covered, {-7'000, 5'000}, false));
    const ResolvedMachine odd = test::fdmMachine({{"adhesion_type", "brim"}, {"brim_line_count", "5"}});
    EXPECT_EQ(boundsOf(brimCoveredArea(odd.global, &odd.extruders, ring)).left, -2'400);  // rounded up to 6
    const ResolvedMachine off =
        test::fdmMachine({{"adhesion_type", "brim"}, {"brim_replaces_support", "False"}});
    EXPECT_TRUE(brimCoveredArea(off.global, &off.extruders, ring).empty());
    const ResolvedMachine skirt = test::fdmMachine({{"adhesion_type", "skirt"}});
    EXPECT_TRUE(brimCoveredArea(skirt.global, &skirt.extruders, ring).empty());
}

}  // namespace
}  // namespace mixengine
