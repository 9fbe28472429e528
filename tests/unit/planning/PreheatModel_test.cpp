// CuraEngine's heater model (planning/PreheatModel.h), with the Ultimaker S5's rates: heating at
// 1.4 °C/s, cooling at 0.8 °C/s, the flowing material taking 0.7 °C/s more while printing.
#include "planning/PreheatModel.h"

#include <gtest/gtest.h>

namespace mixengine {
namespace {

const HeaterRates kS5{1.4, 0.8, 0.7};

TEST(PreheatModel, SecondsToReachIdleAndWhilePrinting) {
    EXPECT_DOUBLE_EQ(secondsToReach(kS5, 100, 200, false), 100 / 1.4);
    EXPECT_DOUBLE_EQ(secondsToReach(kS5, 100, 200, true), 100 / 0.7);  // 1.4 − 0.7
    EXPECT_DOUBLE_EQ(secondsToReach(kS5, 200, 185, true), 15 / 1.5);   // 0.8 + 0.7
    EXPECT_DOUBLE_EQ(secondsToReach(kS5, 200, 200, false), 0);
}

// Idle for 300 s from 185 °C, needed at 190 °C again: it cools all the way to the 100 °C standby
// and must start heating 90 / 1.4 s before the end.
TEST(PreheatModel, WarmUpWithTimeToReachTheStandbyTemperature) {
    const WarmUp w = warmUpAfterCoolDown(kS5, 300, 185, 100, 190, false);
    EXPECT_DOUBLE_EQ(w.window_s, 300);
    EXPECT_DOUBLE_EQ(w.lowest_c, 100);
    EXPECT_NEAR(w.heating_s, 5 / 1.4 + 85 / 1.4,
                1e-9);  // the 5 °C above the start, then back from 100 to 185
}

// Idle for 40 s: cooling from 185 at 0.8 °C/s and heating back at 1.4 °C/s share the time left after the
// 5 °C of extra heating; it turns around above the standby temperature.
TEST(PreheatModel, WarmUpInAShortWindowTurnsAroundEarlier) {
    const WarmUp w = warmUpAfterCoolDown(kS5, 40, 185, 100, 190, false);
    const double free_s = 40 - 5 / 1.4;
    const double back_up_s = free_s * (1 / 1.4) / (1 / 0.8 + 1 / 1.4);
    EXPECT_NEAR(w.heating_s, 5 / 1.4 + back_up_s, 1e-9);
    EXPECT_NEAR(w.lowest_c, 190 - w.heating_s * 1.4, 1e-9);
    EXPECT_GT(w.lowest_c, 100);
    EXPECT_LT(w.lowest_c, 185);
}

TEST(PreheatModel, WarmUpWithoutTimeForTheDirectChange) {
    const WarmUp w = warmUpAfterCoolDown(kS5, 2, 150, 100, 200, false);
    EXPECT_EQ(w.heating_s, 0);
    EXPECT_EQ(w.lowest_c, 150);
}

// Printing 200 s from 190 °C at 200 °C, to end at 185 °C: cooling by 15 °C at 1.5 °C/s while printing
// must start 10 s before the end; a window too short to reach 200 °C stays lower.
TEST(PreheatModel, CoolDownAfterWarmUp) {
    const CoolDown c = coolDownAfterWarmUp(kS5, 200, 190, 200, 185, true);
    EXPECT_DOUBLE_EQ(c.highest_c, 200);
    EXPECT_NEAR(c.cooling_s, 5 / 1.5 + 10 / 1.5, 1e-9);
    const CoolDown short_window = coolDownAfterWarmUp(kS5, 12, 190, 200, 185, true);
    EXPECT_LT(short_window.highest_c, 200);
    EXPECT_GT(short_window.highest_c, 190);
    const CoolDown none = coolDownAfterWarmUp(kS5, 1, 190, 200, 185, true);
    EXPECT_EQ(none.cooling_s, 0);
    EXPECT_EQ(none.highest_c, 190);
}

}  // namespace
}  // namespace mixengine
