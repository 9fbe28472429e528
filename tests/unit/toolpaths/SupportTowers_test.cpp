// Support towers (toolpaths/support/SupportTowers.h) under a hook: a 2 mm arm out of a wall whose end hangs
// down.
#include "toolpaths/support/SupportTowers.h"

#include <gtest/gtest.h>

#include <cmath>

#include "ToolpathTestSupport.h"
#include "geometry/PolygonOps.h"
#include "toolpaths/support/SupportAreas.h"

namespace mixengine {
namespace {

using test::rect;

/// A 20 x 4 mm wall on every layer; a 2 x 8 mm arm (x 9 … 11, y 4 … 12 mm) on layers 45 … 54; its
/// end (x 9 … 11, y 10 … 12 mm) hangs down to layer 35. Layers are 0.1 mm.
test::Stack hook() {
    test::Stack s = test::prismStack(60);
    test::fill(s, 0, 60, {rect(0, 0, 20'000, 4'000)});
    test::fill(s, 35, 45, {rect(0, 0, 20'000, 4'000), rect(9'000, 10'000, 11'000, 12'000)});
    test::fill(s, 45, 55, {rect(0, 0, 20'000, 4'000), rect(9'000, 4'000, 11'000, 12'000)});
    return s;
}

SupportTowerParams towers() {
    SupportTowerParams t;
    t.max_supported_diameter_um = 3'000;
    t.diameter_um = 3'000;
    t.roof_step_um = static_cast<coord_um>(100 / std::tan(65 * M_PI / 180));  // 46 µm a layer
    return t;
}

std::vector<SupportLayerAreas> supportOf(const test::Stack& s, const SupportTowerParams& t) {
    std::vector<Paths> model;
    for (const SlicedLayer& layer : s.layers)
        model.push_back(layer.outlines);
    Overhangs o = detectOverhangs(s.layers, s.heights, 50, 2);
    o.points = detectOverhangPoints(s.layers, t.max_supported_diameter_um, 200, nullptr);
    SupportAreaParams p;
    p.join_distance_um = 2'000;
    p.towers = t;
    return computeSupportAreas(model, o, p, 2);
}

/// The support under the hanging end (y beyond 8 mm: away from the arm's own support).
Paths underTheEnd(const SupportLayerAreas& layer) {
    return intersectAll(layer.support, {rect(0, 8'000, 20'000, 20'000)});
}

TEST(SupportTowers, TheHangingEndIsTheOnlyOverhangPoint) {
    const test::Stack s = hook();
    const std::vector<std::vector<Paths>> points = detectOverhangPoints(s.layers, 3'000, 200, nullptr);
    for (int i = 0; i < 60; ++i)
        EXPECT_EQ(points[i].size(), i == 35 ? 1u : 0u) << i;
    // The end's outline inset by 0.2 mm.
    const ClipperLib::IntRect box = boundsOf(points[35][0]);
    EXPECT_EQ(box.left, 9'200);
    EXPECT_EQ(box.right, 10'800);
    EXPECT_EQ(box.top, 10'200);
    EXPECT_EQ(box.bottom, 11'800);
    EXPECT_EQ(areaUm2(points[35][0]), 1'600.0 * 1'600.0);
    // Larger than the maximum diameter squared: no point.
    EXPECT_TRUE(detectOverhangPoints(s.layers, 2'000, 200, nullptr)[35].empty());
}

TEST(SupportTowers, ATowerOfTheDiameterStandsUnderTheHangingEnd) {
    const test::Stack s = hook();
    const std::vector<SupportLayerAreas> with = supportOf(s, towers());
    const std::vector<SupportLayerAreas> without = supportOf(s, {});
    // Right under the end the tower's roof is still within the end's own support (2 x 2 mm).
    for (int i : {33, 30}) {
        EXPECT_EQ(underTheEnd(with[i]), underTheEnd(without[i])) << i;
        EXPECT_EQ(areaUm2(underTheEnd(without[i])), 2'000.0 * 4'000.0) << i;  // the end and the arm's
    }
    // Going down the roof widens 46 µm a layer on every side, and stops at the tower's diameter:
    // from layer 20 to the plate a 3.07 mm wide column (diameter² reached) centred under the end (x 10, y 11
    // mm).
    const ClipperLib::IntRect wider = boundsOf(underTheEnd(with[25]));
    EXPECT_GT(wider.right - wider.left, 2'000 + 2 * 46 * 4);
    EXPECT_LT(wider.right - wider.left, 3'000);
    for (int i : {10, 5, 0}) {
        const ClipperLib::IntRect box = boundsOf(underTheEnd(with[i]));
        EXPECT_EQ(box.left + box.right, 2 * 10'000) << i;
        EXPECT_EQ(box.bottom, 11'000 + (box.right - box.left) / 2) << i;
        EXPECT_GE(box.right - box.left, 3'000) << i;
        EXPECT_LT(box.right - box.left, 3'000 + 2 * 46) << i;
        // From a square point the tower stays square (as CuraEngine's: its bevels at a miter limit
        // of 1.2 are lost in the join), so its area is about the diameter squared.
        const double beyond_the_arm =
            areaUm2(intersectAll(with[i].support, {rect(0, 10'000, 20'000, 20'000)}));
        EXPECT_NEAR(beyond_the_arm, double(box.right - box.left) * double(box.bottom - 10'000), 0.01e6) << i;
        EXPECT_EQ(boundsOf(underTheEnd(without[i])).left, 9'000) << i;  // no tower: the end's 2 mm
        EXPECT_EQ(boundsOf(underTheEnd(without[i])).right, 11'000) << i;
    }
}

TEST(SupportTowers, ASmallSupportIslandUnderAPinBecomesATower) {
    // A 1.2 x 2 mm pin out of the wall on layers 40 … 51: its support (2.4 mm², smaller than the maximum
    // diameter squared) has support six layers up and no model below, so a roof starts and widens.
    test::Stack s = test::prismStack(60);
    test::fill(s, 0, 60, {rect(0, 0, 20'000, 4'000)});
    test::fill(s, 40, 52, {rect(0, 0, 20'000, 4'000), rect(9'400, 4'000, 10'600, 6'000)});
    const std::vector<SupportLayerAreas> with = supportOf(s, towers());
    const std::vector<SupportLayerAreas> without = supportOf(s, {});
    const Paths beside_the_wall = {rect(0, 4'000, 20'000, 20'000)};
    for (int i : {36, 32}) {  // the six layers under the pin's support, and the roof's first layer
        EXPECT_EQ(intersectAll(with[i].support, beside_the_wall),
                  intersectAll(without[i].support, beside_the_wall))
            << i;
    }
    for (int i : {10, 5}) {
        const ClipperLib::IntRect box = boundsOf(intersectAll(with[i].support, beside_the_wall));
        const ClipperLib::IntRect pin = boundsOf(intersectAll(without[i].support, beside_the_wall));
        EXPECT_EQ(pin.right - pin.left, 1'200) << i;
        EXPECT_EQ(box.left + box.right, 2 * 10'000) << i;
        // A roof starts on every layer while the island is small, each growing until its area reaches
        // 9 mm², so the column keeps widening a little: 2.95 mm on layer 10, 3.13 mm on layer 5.
        EXPECT_GT(box.right - box.left, 2'800) << i;
        EXPECT_LT(box.right - box.left, 3'300) << i;
        EXPECT_GE(areaUm2(with[i].support), 9e6 - 4'000.0 * 700 - 1e6) << i;  // less the wall's xy distance
    }
}

}  // namespace
}  // namespace mixengine
