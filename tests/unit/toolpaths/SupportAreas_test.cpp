// Support areas (toolpaths/support/SupportAreas.h) under a T shape and an H shape.
#include "toolpaths/support/SupportAreas.h"

#include <gtest/gtest.h>

#include "ToolpathTestSupport.h"
#include "geometry/PolygonOps.h"

namespace mixengine {
namespace {

using test::rect;

/// A 10 mm stem (x, y in 0 … 10 mm) on layers [stem_from, 50), a 30 mm wide plate (x −10 … 20 mm)
/// on layers 50 … 59; with a base like the plate on layers [0, stem_from) when stem_from > 0.
test::Stack tee(int stem_from = 0) {
    test::Stack s = test::prismStack(60);
    test::fill(s, 0, stem_from, {rect(-10'000, 0, 20'000, 10'000)});
    test::fill(s, stem_from, 50, {rect(0, 0, 10'000, 10'000)});
    test::fill(s, 50, 60, {rect(-10'000, 0, 20'000, 10'000)});
    return s;
}

std::vector<SupportLayerAreas> supportOf(const test::Stack& s, const SupportAreaParams& p) {
    std::vector<Paths> model;
    for (const SlicedLayer& layer : s.layers)
        model.push_back(layer.outlines);
    return computeSupportAreas(model, detectOverhangs(s.layers, s.heights, 50, 2), p, 2);
}

SupportAreaParams defaults() {
    SupportAreaParams p;
    p.join_distance_um = 2'000;
    return p;
}

TEST(SupportAreas, OverhangsOfTheTee) {
    const test::Stack s = tee();
    const Overhangs o = detectOverhangs(s.layers, s.heights, 50, 1);
    for (int i = 0; i < 60; ++i)
        EXPECT_EQ(o.basic[i].empty(), i != 50) << i;
    // Beyond the stem grown by 0.1 · (tan 50° − 0.01) mm = 118 µm, on both sides.
    EXPECT_EQ(areaUm2(o.basic[50]), 2 * (10'000.0 - 118) * 10'000.0);
    EXPECT_EQ(areaUm2(o.full[50]), 2 * (10'000.0 + 100) * 10'000.0);  // grown by 218 µm within the plate
}

TEST(SupportAreas, UnderTheArmsKeepingTheXYDistanceAndOneEmptyLayer) {
    const test::Stack s = tee();
    const std::vector<SupportLayerAreas> support = supportOf(s, defaults());
    const Paths stem_zone = offsetPolygons({rect(0, 0, 10'000, 10'000)}, 700 - 1);
    for (int i = 0; i < 60; ++i) {
        const Paths& a = support[i].support;
        EXPECT_EQ(!a.empty(), i <= 48) << i;  // layer 49 stays empty under the plate at layer 50
        EXPECT_TRUE(intersectAll(a, stem_zone).empty()) << i;
        if (i <= 48) {  // x −10 … −0.7 and 10.7 … 20 mm, y 0 … 10 mm
            EXPECT_EQ(areaUm2(a), 2 * 9'300.0 * 10'000.0) << i;
        }
    }
}

TEST(SupportAreas, TopDistanceInLayers) {
    SupportAreaParams p = defaults();
    p.top_gap_layers = 3;
    const std::vector<SupportLayerAreas> support = supportOf(tee(), p);
    EXPECT_FALSE(support[46].support.empty());
    EXPECT_TRUE(support[47].support.empty());
}

TEST(SupportAreas, EverywhereRestsOnTheModelBuildplateDoesNot) {
    const test::Stack s = tee(10);  // a base as wide as the plate on layers 0 … 9
    SupportAreaParams p = defaults();
    p.bottom_gap_layers = 2;
    const std::vector<SupportLayerAreas> everywhere = supportOf(s, p);
    for (int i = 0; i < 50; ++i)
        EXPECT_EQ(!everywhere[i].support.empty(), i >= 12 && i <= 48) << i;
    p.buildplate_only = true;
    for (const SupportLayerAreas& layer : supportOf(s, p))
        EXPECT_TRUE(layer.support.empty());
}

TEST(SupportAreas, RoofAndFloorInterfaces) {
    SupportAreaParams p = defaults();
    p.roof_layers = 3;
    p.floor_layers = 2;
    const std::vector<SupportLayerAreas> support = supportOf(tee(10), p);
    // Roof: layers 46 … 48 (within top gap + 3 layers of the plate); floor: layers 10 … 11 are
    // blocked by the bottom gap (1 layer), so 11 … 12 sit within the base's reach.
    for (int i = 46; i <= 48; ++i) {
        EXPECT_FALSE(support[i].roof.empty()) << i;
        EXPECT_TRUE(support[i].support.empty()) << i;
    }
    EXPECT_TRUE(support[45].roof.empty());
    EXPECT_FALSE(support[45].support.empty());
    EXPECT_FALSE(support[11].floor.empty());
    EXPECT_FALSE(support[12].floor.empty());
    EXPECT_TRUE(support[13].floor.empty());
}

TEST(SupportAreas, InterfaceOffsetAndMinimumAreaAsCuraEngine) {
    SupportAreaParams p = defaults();
    p.roof_layers = 3;
    p.roof_line_width_um = 400;  // the margin stays within the support: each arm is roof whole
    const double arm = 9'300.0 * 10'000.0;
    EXPECT_EQ(areaUm2(supportOf(tee(), p)[48].roof), 2 * arm);
    p.roof_offset_um = -1'000;  // shrunk 1 mm: 7.3 × 8 mm per arm, the rest is body
    const std::vector<SupportLayerAreas> shrunk = supportOf(tee(), p);
    EXPECT_EQ(areaUm2(shrunk[48].roof), 2 * 7'300.0 * 8'000.0);
    EXPECT_EQ(areaUm2(shrunk[48].support), 2 * (arm - 7'300.0 * 8'000.0));
    p.min_roof_area_um2 = 60e6;  // each 58.4 mm² roof is too small: all body
    const std::vector<SupportLayerAreas> dropped = supportOf(tee(), p);
    EXPECT_TRUE(dropped[48].roof.empty());
    EXPECT_EQ(areaUm2(dropped[48].support), 2 * arm);
}

}  // namespace
}  // namespace mixengine

namespace mixengine {
namespace {

TEST(SupportAreas, ConicalSupportNarrowsGoingDownUnlessNarrowerThanTheMinimumWidth) {
    const test::Stack s = tee();
    SupportAreaParams p = defaults();
    p.conical_step_um = -50;  // 0.1 mm layers, (tan 30° − 0.01) · 100 µm = 56 µm, rounded here
    p.conical_min_width_um = 1'000;
    const std::vector<SupportLayerAreas> conical = supportOf(s, p);
    const std::vector<SupportLayerAreas> straight = supportOf(s, defaults());
    // Each arm (9.3 × 10 mm next to the stem) loses 50 µm per layer on its three free sides.
    EXPECT_LT(areaUm2(conical[40].support), areaUm2(conical[47].support));
    EXPECT_LT(areaUm2(conical[20].support), areaUm2(straight[20].support) - 2 * 28 * 50 * 20'000.0);
    EXPECT_GT(areaUm2(conical[0].support), 0);
    p.conical_min_width_um = 30'000;  // wider than the arms: nothing shrinks
    const std::vector<SupportLayerAreas> kept = supportOf(s, p);
    EXPECT_NEAR(areaUm2(kept[0].support), areaUm2(straight[0].support), 1e6);
}

TEST(SupportAreas, TheJoinedAreasNotchIsSmoothedOutward) {
    // An L-shaped plate on layers 50 … 59 over a small stem in its far corner: the support under it
    // keeps the L's 90° notch at (0, 0) unless smoothed, when a 400 µm shortcut fills it (ends
    // 283 µm from the corner: 283² / 2 µm² more on every layer).
    test::Stack s = test::prismStack(60);
    const Path l{{-10'000, -10'000}, {10'000, -10'000}, {10'000, 0}, {0, 0}, {0, 10'000}, {-10'000, 10'000}};
    test::fill(s, 0, 50, {rect(-10'000, -10'000, -8'000, -8'000)});
    test::fill(s, 50, 60, {l});
    const std::vector<SupportLayerAreas> sharp = supportOf(s, defaults());
    SupportAreaParams p = defaults();
    p.smoothing_um = 400;
    const std::vector<SupportLayerAreas> smooth = supportOf(s, p);
    for (const int layer : {20, 45})
        EXPECT_NEAR(areaUm2(smooth[layer].support) - areaUm2(sharp[layer].support), 283.0 * 283.0 / 2,
                    2'000.0)
            << layer;
}

}  // namespace
}  // namespace mixengine
