// The chamber model (mixing/chamber/ChamberModel.h) against the analytic responses of stirred tanks in
// series, written here from the textbook formulas (not from the engine's closed form).
#include "mixing/chamber/ChamberModel.h"

#include <gtest/gtest.h>

#include <cmath>

namespace mixengine {
namespace {

const MixVector kA = MixVector::only(0, 2);
const MixVector kB = MixVector::only(1, 2);

/// Share of the new mix leaving N tanks after a step change, t = pushed volume / tank volume.
double stepResponse(int stages, double t) {
    double sum = 0, term = 1;
    for (int i = 0; i < stages; ++i) {
        sum += term;
        term *= t / (i + 1);
    }
    return 1 - std::exp(-t) * sum;
}

TEST(MixingChamberModel, OneTankIsAnExponential) {
    Chamber chamber({40, 1}, kA);
    chamber.push(kB, 40);
    EXPECT_NEAR(chamber.outlet()[1], 1 - std::exp(-1.0), 1e-12);
}

TEST(MixingChamberModel, ThreeTanksFollowTheGammaStepResponse) {
    for (double v : {1.0, 13.3, 40.0, 71.0, 150.0}) {
        Chamber chamber({40, 3}, kA);
        chamber.push(kB, v);
        EXPECT_NEAR(chamber.outlet()[1], stepResponse(3, v * 3 / 40), 1e-12) << v;
    }
}

TEST(MixingChamberModel, PushesInPiecesEqualOnePush) {
    Chamber whole({40, 3}, kA), pieces({40, 3}, kA);
    whole.push(kB, 37);
    for (int i = 0; i < 37; ++i)
        pieces.push(kB, 1);
    EXPECT_NEAR(whole.outlet()[1], pieces.outlet()[1], 1e-12);
}

TEST(MixingChamberModel, WhatLeavesDuringAPushIsTheAverageOfTheOutlet) {
    // The average over [0, T] of the step response, by the trapezoid rule on fine steps.
    const double total = 30;
    double integral = 0;
    const int n = 30000;
    for (int i = 0; i < n; ++i) {
        const double a = stepResponse(3, (total * i / n) * 3 / 40),
                     b = stepResponse(3, (total * (i + 1) / n) * 3 / 40);
        integral += (a + b) / 2 * (total / n);
    }
    Chamber chamber({40, 3}, kA);
    EXPECT_NEAR(chamber.push(kB, total)[1], integral / total, 1e-7);
}

TEST(MixingChamberModel, WhatLeavesAMixedChamberIsTheAverageOfItsOutlet) {
    // From a chamber whose tanks differ (part way through a change), the average of a push is the mean of
    // the outlet over the push: the trapezoid rule over 20000 small pushes of the same chamber.
    Chamber whole({40, 3}, kA);
    whole.push(kB, 25);
    Chamber small = whole;
    const double total = 30;
    const int n = 20000;
    double integral = 0, before = small.outlet()[1];
    for (int i = 0; i < n; ++i) {
        small.push(kA, total / n);
        integral += (before + small.outlet()[1]) / 2 * (total / n);
        before = small.outlet()[1];
    }
    EXPECT_NEAR(whole.push(kA, total)[1], integral / total, 1e-7);
}

TEST(MixingChamberModel, AFullChangeToATenthNeedsSeventyOneCubicMillimetres) {
    // e^-t (1 + t + t²/2) = 0.1 at t = 5.3223 tank volumes of 40/3 mm³ (issue 26: "about 71 mm³").
    EXPECT_NEAR(fullChangeVolumeMm3({40, 3}, 0.1), 70.964, 0.02);
    EXPECT_NEAR(fullChangeVolumeMm3({40, 1}, 0.1), 40 * std::log(10.0), 0.02);
}

TEST(MixingChamberModel, VolumeToReachIsZeroWhenSettledAndExactOtherwise) {
    Chamber settled({40, 3}, kB);
    EXPECT_EQ(settled.volumeToReach(kB, 0.1), 0);
    Chamber half({40, 3}, kA);
    half.push(kB, 20);  // part of the way
    const double more = half.volumeToReach(kB, 0.1);
    EXPECT_NEAR(20 + more, 70.964, 0.03);
}

TEST(MixingChamberModel, AnIdealChamberPassesTheMixAtOnce) {
    Chamber ideal({0, 3}, kA);
    EXPECT_EQ(ideal.push(kB, 0.001)[1], 1.0);
    EXPECT_EQ(ideal.volumeToReach(kA, 0.01), 0);
}

TEST(MixingChamberModel, ShareDistanceIsTheLargestChannelDifference) {
    MixVector m;
    m.channels = 3;
    m[0] = 0.5;
    m[1] = 0.3;
    m[2] = 0.2;
    EXPECT_NEAR(shareDistance(m, MixVector::only(0, 3)), 0.5, 1e-12);
}

}  // namespace
}  // namespace mixengine
