// Outline clean-up (slicing/OutlineCleanup.h): small loops dropped, fine detail removed within
// the deviation, collinear points removed, long edges kept.
#include "slicing/OutlineCleanup.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace mixengine {
namespace {

Path circle(coord_um radius, int vertices) {
    Path p;
    for (int i = 0; i < vertices; ++i) {
        const double a = 2 * std::numbers::pi * i / vertices;
        p.push_back({std::llround(radius * std::cos(a)), std::llround(radius * std::sin(a))});
    }
    return p;
}

double distanceToLoop(const Point2& p, const Path& loop) {
    double best = 1e300;
    for (std::size_t i = 0; i < loop.size(); ++i) {
        const Point2& a = loop[i];
        const Point2& b = loop[(i + 1) % loop.size()];
        const double dx = double(b.X - a.X), dy = double(b.Y - a.Y);
        double t = ((p.X - a.X) * dx + (p.Y - a.Y) * dy) / (dx * dx + dy * dy);
        t = std::clamp(t, 0.0, 1.0);
        best = std::min(best, std::hypot(a.X + t * dx - p.X, a.Y + t * dy - p.Y));
    }
    return best;
}

TEST(OutlineCleanup, FineCircleLosesVerticesWithinTheDeviation) {
    const Path fine = circle(10'000, 4000);  // 15.7 µm edges
    const Path simple = simplifyLoop(fine, 500, 25);
    EXPECT_LT(simple.size(), 400U);
    EXPECT_GT(simple.size(), 50U);
    for (const Point2& p : fine)
        EXPECT_LE(distanceToLoop(p, simple), 25.0 + 1.0);
}

TEST(OutlineCleanup, CollinearPointsGoLongEdgesStay) {
    const Path square{{0, 0}, {5'000, 0}, {10'000, 0}, {10'000, 10'000}, {0, 10'000}};
    EXPECT_EQ(simplifyLoop(square, 500, 25), (Path{{0, 0}, {10'000, 0}, {10'000, 10'000}, {0, 10'000}}));
    // A 1 mm notch is deeper than the deviation: it stays.
    const Path notch{{0, 0},      {4'000, 0},       {5'000, 1'000}, {6'000, 0},
                     {10'000, 0}, {10'000, 10'000}, {0, 10'000}};
    EXPECT_EQ(simplifyLoop(notch, 500, 25).size(), notch.size());
}

// simplifyLoops: each loop as simplifyLoop makes it; a loop left with under three vertices goes; limits 0: as
// given.
TEST(OutlineCleanup, SimplifyLoopsSimplifiesEachAndDropsDegenerateOnes) {
    const Path square{{0, 0}, {5'000, 0}, {10'000, 0}, {10'000, 10'000}, {0, 10'000}};
    const Path sliver{{0, 0}, {10'000, 0}};  // under three vertices
    const Paths simplified = simplifyLoops({square, sliver}, 500, 25);
    ASSERT_EQ(simplified.size(), 1U);
    EXPECT_EQ(simplified[0], simplifyLoop(square, 500, 25));
    EXPECT_EQ(simplifyLoops({square, sliver}, 0, 0), (Paths{square, sliver}));
}

TEST(OutlineCleanup, SmallLoopsAreShorterThanTheMinimumCircumference) {
    EXPECT_TRUE(loopShorterThan(circle(100, 16), 1'000));  // circumference 0.63 mm < 1 mm
    EXPECT_FALSE(loopShorterThan(circle(10'000, 64), 1'000));
    // A 250 µm square is 1000 µm round: not shorter than 1000, shorter than 1001.
    const Path square{{0, 0}, {250, 0}, {250, 250}, {0, 250}};
    EXPECT_FALSE(loopShorterThan(square, 1'000));
    EXPECT_TRUE(loopShorterThan(square, 1'001));
}

TEST(OutlineCleanup, RemoveHolesFillsThemAndMergesWhatWasInside) {
    // A 30 mm square with a 10 mm hole holding a 4 mm island: one filled square is left.
    const Path outer{{0, 0}, {30'000, 0}, {30'000, 30'000}, {0, 30'000}};
    const Path hole{{10'000, 10'000}, {10'000, 20'000}, {20'000, 20'000}, {20'000, 10'000}};  // clockwise
    const Path island{{13'000, 13'000}, {17'000, 13'000}, {17'000, 17'000}, {13'000, 17'000}};
    std::vector<SlicedLayer> layers(2);
    layers[0].outlines = {outer, hole, island};
    layers[1].outlines = {island};
    removeHoles(layers, 2);
    ASSERT_EQ(layers[0].outlines.size(), 1U);
    EXPECT_DOUBLE_EQ(ClipperLib::Area(layers[0].outlines[0]), 900e6);
    ASSERT_EQ(layers[1].outlines.size(), 1U);
    EXPECT_DOUBLE_EQ(ClipperLib::Area(layers[1].outlines[0]), 16e6);
}

}  // namespace
}  // namespace mixengine
