// Nozzle temperature commands (gcode/TemperatureCommands.h): what CuraEngine 4.13 writes and drops.
#include "gcode/TemperatureCommands.h"

#include <gtest/gtest.h>

namespace mixengine {
namespace {

using Lines = std::vector<std::string>;

TEST(TemperatureCommands, SetWaitOtherNozzleAndNothingTwice) {
    TemperatureCommands t;
    t.assume(0, 200, true);                      // the start code waited for 200 °C
    EXPECT_EQ(t.set(0, 200, true, 0), Lines{});  // at 200 and waited for already
    EXPECT_EQ(t.set(1, 153.94, false, 0), Lines{"M104 T1 S153.9"});
    EXPECT_EQ(t.set(1, 153.94, false, 0), Lines{});
    EXPECT_EQ(t.set(1, 153.94, true, 0), Lines{"M109 T1 S153.9"});  // set, but never waited for
    EXPECT_EQ(t.set(0, 185, false, 0), Lines{"M104 S185"});
    EXPECT_EQ(t.set(0, 190, true, 1), Lines{"M109 T0 S190"});
}

TEST(TemperatureCommands, MarlinAsksForTemperaturesBeforeWaiting) {
    TemperatureCommands t({false, false, {}}, true);
    EXPECT_EQ(t.set(0, 210, true, 0), (Lines{"M105", "M109 S210"}));
    EXPECT_EQ(t.set(0, 200, false, 0), Lines{"M104 S200"});
}

TEST(TemperatureCommands, ActiveToolWrittenAgainAfterNamingAnother) {
    TemperatureCommands t({false, true, {}}, false);
    EXPECT_EQ(t.set(1, 100, false, 0), (Lines{"M104 T1 S100", "T0"}));
    EXPECT_EQ(t.set(0, 200, false, 0), Lines{"M104 S200"});
}

// One heater for both nozzles: commands for the idle nozzle are dropped, and the active one's setting
// holds for both (switching to T1 at the same temperature needs no wait).
TEST(TemperatureCommands, SharedHeaterFollowsTheActiveNozzleOnly) {
    TemperatureCommands t({true, false, {true, true}}, false);
    EXPECT_EQ(t.set(1, 150, false, 0), Lines{});
    EXPECT_EQ(t.set(0, 210, true, 0), Lines{"M109 S210"});
    EXPECT_EQ(t.set(1, 210, true, 1), Lines{});
    EXPECT_EQ(t.set(1, 200, false, 1), Lines{"M104 S200"});
}

TEST(TemperatureCommands, NothingForANozzleWithoutTemperatureControl) {
    TemperatureCommands t({false, false, {true, false}}, false);
    EXPECT_EQ(t.set(1, 200, true, 1), Lines{});
    EXPECT_EQ(t.set(0, 200, false, 1), Lines{"M104 T0 S200"});
}

}  // namespace
}  // namespace mixengine
