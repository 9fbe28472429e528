// Bridged skin (toolpaths/skin/BridgeSkin.h): which skin parts are bridges and along which angle their
// lines run, as CuraEngine 4.13's bridge.cpp decides.
#include "toolpaths/skin/BridgeSkin.h"

#include <gtest/gtest.h>

namespace mixengine {
namespace {

Path box(coord_um x0, coord_um y0, coord_um x1, coord_um y1) {
    return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

BridgeSkinParams params() {
    BridgeSkinParams p;
    p.enabled = true;
    p.more_layers = true;
    p.support_threshold = 0.5;
    p.sparse_infill = true;
    p.bottom_layers = 3;
    p.overlap_um = 200;
    p.layers[0] = {12.5, 0.9, 1.0, 1.0};
    p.layers[1] = {20, 1.1, 0.75, 0.0};
    p.layers[2] = {25, 1.2, 0.8, 0.0};
    return p;
}

SkinFillParams skin() {
    SkinFillParams s;
    s.pattern = InfillPattern::ZigZag;
    s.angle_degrees = 45;
    s.style.width_um = 400;
    s.style.speed_mm_s = 30;
    return s;
}

// A 30 × 10 mm deck on two 5 mm wide pillars: a third of it rests on them.
const Paths kDeck{box(0, 0, 30'000, 10'000)};
const Paths kPillars{box(0, 0, 5'000, 10'000), box(25'000, 0, 30'000, 10'000)};

TEST(BridgeSkin, ADeckOnTwoPillarsIsABridgeAlongItsEdgesOverAir) {
    const std::vector<Paths> outlines{kPillars, kDeck};
    const std::optional<SkinFillParams> fill =
        bridgeSkinFill(kDeck, skin(), params(), {&outlines, nullptr, 1});
    ASSERT_TRUE(fill);
    EXPECT_EQ(int(fill->angle_degrees) % 180, 90);  // along x: the long edges over the gap
    EXPECT_EQ(fill->pattern, InfillPattern::Lines);
    EXPECT_DOUBLE_EQ(fill->style.speed_mm_s, 12.5);
    EXPECT_DOUBLE_EQ(fill->style.flow, 0.9);
    EXPECT_EQ(fill->overlap_um, 200);
    EXPECT_EQ(fill->bridge_fan_ratio, 1.0);
}

TEST(BridgeSkin, ASupportedPartOrSettingsOffIsNoBridge) {
    const std::vector<Paths> outlines{kDeck, kDeck};
    EXPECT_FALSE(bridgeSkinFill(kDeck, skin(), params(), {&outlines, nullptr, 1}));
    const std::vector<Paths> pillars{kPillars, kDeck};
    BridgeSkinParams off = params();
    off.enabled = false;
    EXPECT_FALSE(bridgeSkinFill(kDeck, skin(), off, {&pillars, nullptr, 1}));
}

TEST(BridgeSkin, SparseInfillBelowCountsAsAirUpToTheMaximumDensity) {
    const std::vector<Paths> outlines{kDeck, kDeck};
    const std::vector<Paths> infill{{box(5'000, 0, 25'000, 10'000)}, {}};
    EXPECT_TRUE(bridgeSkinFill(kDeck, skin(), params(), {&outlines, &infill, 1}));
    BridgeSkinParams dense = params();
    dense.sparse_infill = false;
    EXPECT_FALSE(bridgeSkinFill(kDeck, skin(), dense, {&outlines, &infill, 1}));
}

TEST(BridgeSkin, TheSecondBridgeLayerTurns45DegreesWithItsOwnSettings) {
    const std::vector<Paths> outlines{kPillars, kDeck, kDeck};
    const std::optional<SkinFillParams> fill =
        bridgeSkinFill(kDeck, skin(), params(), {&outlines, nullptr, 2});
    ASSERT_TRUE(fill);
    EXPECT_EQ(int(fill->angle_degrees) % 180, 135);
    EXPECT_DOUBLE_EQ(fill->style.speed_mm_s, 20);
    EXPECT_DOUBLE_EQ(fill->density, 0.75);
    EXPECT_EQ(fill->bridge_fan_ratio, 0.0);
    BridgeSkinParams one = params();
    one.more_layers = false;
    EXPECT_FALSE(bridgeSkinFill(kDeck, skin(), one, {&outlines, nullptr, 2}));
}

TEST(BridgeSkin, WithoutEdgesOverAirTheLineJoinsTheTwoLargestIslands) {
    // a part whose whole outline rests on the ring below, with air inside: the islands decide
    const Paths islands{box(0, 0, 4'000, 4'000), box(10'000, 0, 14'000, 4'000)};
    EXPECT_EQ(
        bridgeLineAngle(Paths{box(0, 0, 14'000, 4'000)}, Paths{box(-1'000, -1'000, 15'000, 5'000)}, islands),
        90);
}

}  // namespace
}  // namespace mixengine
