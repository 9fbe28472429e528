// The mix schedule (mixing/fields/MixSchedule.h): seed 001's three cases for its four printed examples,
// the hard switch, multi-stop gradients, mm units and the fixed ratio of dual mode.
#include "mixing/fields/MixSchedule.h"

#include <gtest/gtest.h>

namespace mixengine {
namespace {

MeshMixing seedGradient(double color_a, double color_b) {
    MeshMixing m;
    m.mode = MixingMode::Gradient;
    m.unit = HeightUnit::Percent;
    m.stops = {{color_a, MixVector::only(0, 2)}, {color_b, MixVector::only(1, 2)}};
    return m;
}

/// Share of B for a layer at `percent` of a 20 mm model, per the seed's three cases.
double seedFormula(double a, double b, double percent) {
    if (percent <= a)
        return 0.0;  // case 1
    if (percent > b)
        return 1.0;                  // case 3
    return (percent - a) / (b - a);  // case 2 (never reached when a == b)
}

TEST(MixingSchedule, SeedExamplesFollowTheThreeCases) {
    const double examples[][2] = {{0, 100}, {20, 80}, {50, 50}, {80, 100}};
    for (const auto& [a, b] : examples) {
        const MeshMixing m = seedGradient(a, b);
        for (int tenth = 0; tenth <= 200; ++tenth) {  // every 0.1 mm of a 20 mm model
            const double z = tenth / 10.0;
            const MixVector mix = targetMix(m, z, 20.0);
            const double expected_b = seedFormula(a, b, 100.0 * z / 20.0);
            EXPECT_NEAR(mix[1], expected_b, 1e-12) << a << "/" << b << " at " << z;
            EXPECT_NEAR(mix[0] + mix[1], 1.0, 1e-12);
        }
    }
}

TEST(MixingSchedule, CaseBoundaries) {
    const MeshMixing m = seedGradient(20, 80);
    EXPECT_EQ(targetMix(m, 4.0, 20.0)[1], 0.0);   // exactly at the start: A only (case 1)
    EXPECT_EQ(targetMix(m, 16.0, 20.0)[1], 1.0);  // exactly at the end: B only (end of case 2)
    EXPECT_DOUBLE_EQ(targetMix(m, 10.0, 20.0)[1], 0.5);
    EXPECT_EQ(targetMix(m, 20.0, 20.0)[0], 0.0);  // above the end (case 3)
}

TEST(MixingSchedule, EqualStartAndEndIsAHardSwitch) {
    const MeshMixing m = seedGradient(50, 50);
    EXPECT_EQ(targetMix(m, 10.0, 20.0), MixVector::only(0, 2));   // 50 %: still A
    EXPECT_EQ(targetMix(m, 10.01, 20.0), MixVector::only(1, 2));  // just above: B
}

TEST(MixingSchedule, MultiStopGradientOverThreeChannels) {
    MixVector c0 = MixVector::only(0, 3), c1 = MixVector::only(1, 3), mid;
    mid.channels = 3;
    mid[1] = 0.5;
    mid[2] = 0.5;
    const std::vector<GradientStop> stops = {{0, c0}, {50, c1}, {100, mid}};
    EXPECT_EQ(mixAtHeight(stops, -5), c0);
    const MixVector quarter = mixAtHeight(stops, 25);
    EXPECT_DOUBLE_EQ(quarter[0], 0.5);
    EXPECT_DOUBLE_EQ(quarter[1], 0.5);
    EXPECT_EQ(quarter[2], 0.0);
    const MixVector upper = mixAtHeight(stops, 75);
    EXPECT_DOUBLE_EQ(upper[1], 0.75);
    EXPECT_DOUBLE_EQ(upper[2], 0.25);
    EXPECT_EQ(mixAtHeight(stops, 120), mid);
}

TEST(MixingSchedule, MillimetresAreAboveTheMeshBottomAndIgnoreItsHeight) {
    MeshMixing m = seedGradient(2, 6);
    m.unit = HeightUnit::Millimetres;
    EXPECT_DOUBLE_EQ(targetMix(m, 4.0, 100.0)[1], 0.5);
    EXPECT_DOUBLE_EQ(targetMix(m, 4.0, 10.0)[1], 0.5);
    // In percent, the same layer height means a different share on a mesh of another height.
    m.unit = HeightUnit::Percent;
    EXPECT_DOUBLE_EQ(targetMix(m, 4.0, 100.0)[1], 0.5);  // 4 % of 100 mm
    EXPECT_EQ(targetMix(m, 4.0, 10.0)[1], 1.0);          // 40 % of 10 mm
}

TEST(MixingSchedule, DualModeIsTheFixedRatioAtEveryHeight) {
    MeshMixing m;
    m.mode = MixingMode::Dual;
    m.fixed.channels = 2;
    m.fixed[0] = 0.3;
    m.fixed[1] = 0.7;
    EXPECT_EQ(targetMix(m, 0.1, 20), m.fixed);
    EXPECT_EQ(targetMix(m, 19.9, 20), m.fixed);
}

}  // namespace
}  // namespace mixengine
