// The acceleration/jerk time estimate (gcode/TimeEstimate.h), against hand-computed trapezoids.
#include "gcode/TimeEstimate.h"

#include <gtest/gtest.h>

#include <cmath>

namespace mixengine {
namespace {

Kinematics kinematics(double acceleration, double jerk_xy) {
    Kinematics k;
    k.acceleration_mm_s2 = acceleration;
    k.max_acceleration_mm_s2 = {1e9, 1e9, 1e9, 1e9};
    k.jerk_xy_mm_s = jerk_xy;
    return k;
}

TEST(TimeEstimateTrapezoid, CruiseAndTriangle) {
    // 0 → 100 mm/s at 1000 mm/s²: 0.1 s and 5 mm each way; 100 mm leaves 90 mm of cruise (0.9 s).
    EXPECT_NEAR(trapezoidSeconds(100, 0, 100, 0, 1000), 1.1, 1e-12);
    // 4 mm is too short to reach 100 mm/s: peak √(1000·4) = 63.25 mm/s, 2 × 0.06325 s.
    EXPECT_NEAR(trapezoidSeconds(4, 0, 100, 0, 1000), 2 * std::sqrt(4000.0) / 1000, 1e-12);
    // Entering and leaving at the nominal speed: distance / speed.
    EXPECT_NEAR(trapezoidSeconds(10, 50, 50, 50, 1000), 0.2, 1e-12);
}

TEST(TimeEstimate, SingleMoveStartsAndEndsNearRest) {
    // Jerk 20: the first move may start at jerk / 2 = 10 mm/s; it ends at rest.
    TimeEstimate t(kinematics(1000, 20));
    t.addMove({100, 0, 0, 0}, 100);
    EXPECT_NEAR(t.totalSeconds(), trapezoidSeconds(100, 10, 100, 0, 1000), 1e-12);
}

TEST(TimeEstimate, StraightContinuationKeepsSpeedCornerSlowsDown) {
    TimeEstimate straight(kinematics(1000, 20));
    straight.addMove({50, 0, 0, 0}, 100);
    straight.addMove({50, 0, 0, 0}, 100);
    TimeEstimate one(kinematics(1000, 20));
    one.addMove({100, 0, 0, 0}, 100);
    EXPECT_NEAR(straight.totalSeconds(), one.totalSeconds(), 1e-9);

    // A right angle: the velocity jump at speed v is v·√2, so the corner speed is 20/√2.
    TimeEstimate corner(kinematics(1000, 20));
    corner.addMove({50, 0, 0, 0}, 100);
    corner.addMove({0, 50, 0, 0}, 100);
    const double v = 20 / std::sqrt(2.0);
    const double expected = trapezoidSeconds(50, 10, 100, v, 1000) + trapezoidSeconds(50, v, 100, 0, 1000);
    EXPECT_NEAR(corner.totalSeconds(), expected, 1e-9);
    EXPECT_GT(corner.totalSeconds(), straight.totalSeconds());
}

TEST(TimeEstimate, FeedrateLimitAndRetraction) {
    Kinematics k = kinematics(1e9, 1e9);
    k.max_feedrate_mm_s = {50, 50, 5, 25};
    TimeEstimate t(k);
    t.addMove({100, 0, 0, 0}, 100);  // limited to 50 mm/s: 2 s
    t.addMove({0, 0, 0, -5}, 100);   // E-only: 5 mm at 25 mm/s
    EXPECT_NEAR(t.totalSeconds(), 2.0 + 0.2, 1e-6);
}

TEST(TimeEstimate, FlushAndDelayAdd) {
    TimeEstimate t(kinematics(1e9, 1e9));
    t.addMove({10, 0, 0, 0}, 10);
    t.flush();
    EXPECT_NEAR(t.totalSeconds(), 1.0, 1e-6);
    t.addDelay(2.5);
    t.addMove({0, 20, 0, 0}, 10);
    EXPECT_NEAR(t.totalSeconds(), 5.5, 1e-6);
}

TEST(TimeEstimate, EachMoveIsBookedToItsFeatureAndTheFeaturesAddUpToTheTotal) {
    // Two moves at rest junctions (E-only retraction between them): each is its own trapezoid.
    Kinematics k = kinematics(1000, 20);
    TimeEstimate t(k);
    t.addMove({100, 0, 0, 0}, 100, TimeFeature::OuterWall);
    t.addMove({0, 0, 0, -5}, 25, TimeFeature::Retraction);
    t.addMove({0, 30, 0, 0}, 150, TimeFeature::Travel);
    t.addDelay(2.5);
    const FeatureSeconds s = t.secondsByFeature();
    EXPECT_GT(s[static_cast<std::size_t>(TimeFeature::OuterWall)], 1.0);    // 100 mm at ≤ 100 mm/s
    EXPECT_GT(s[static_cast<std::size_t>(TimeFeature::Retraction)], 0.2);   // 5 mm at ≤ 25 mm/s
    EXPECT_GT(s[static_cast<std::size_t>(TimeFeature::Travel)], 0.2);       // 30 mm at ≤ 150 mm/s
    EXPECT_DOUBLE_EQ(s[static_cast<std::size_t>(TimeFeature::None)], 2.5);  // the delay
    EXPECT_DOUBLE_EQ(s[static_cast<std::size_t>(TimeFeature::Infill)], 0.0);
    double sum = 0;
    for (double seconds : s)
        sum += seconds;
    EXPECT_NEAR(sum, t.totalSeconds(), 1e-12);
    // The same moves without tags: the same total, all of it None.
    TimeEstimate untagged(k);
    untagged.addMove({100, 0, 0, 0}, 100);
    untagged.addMove({0, 0, 0, -5}, 25);
    untagged.addMove({0, 30, 0, 0}, 150);
    untagged.addDelay(2.5);
    EXPECT_NEAR(untagged.totalSeconds(), t.totalSeconds(), 1e-12);
    EXPECT_NEAR(untagged.secondsByFeature()[0], t.totalSeconds(), 1e-12);
}

}  // namespace
}  // namespace mixengine
