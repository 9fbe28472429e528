// The fan ramp of the first layers (planning/PrintPlanner.h, fanRatioForLayer).
#include <gtest/gtest.h>

#include "planning/PrintPlanner.h"

namespace mixengine {
namespace {

Settings fan(const char* full_layer, const char* enabled = "True") {
    return Settings("mesh group 0", {{"cool_fan_enabled", enabled},
                                     {"cool_fan_speed_0", "0"},
                                     {"cool_fan_speed_min", "100"},
                                     {"cool_fan_full_layer", full_layer}});
}

TEST(PathOrderFanRatio, RampsToRegularSpeedAtFullLayer) {
    // cool_fan_full_layer counts from 1 (as Cura shows it): 4 → regular speed from layer index 3.
    const Settings s = fan("4");
    EXPECT_EQ(fanRatioForLayer(s, 0), 0.0);
    EXPECT_DOUBLE_EQ(fanRatioForLayer(s, 1), 1.0 / 3.0);
    EXPECT_DOUBLE_EQ(fanRatioForLayer(s, 2), 2.0 / 3.0);
    EXPECT_EQ(fanRatioForLayer(s, 3), 1.0);
    EXPECT_EQ(fanRatioForLayer(s, 50), 1.0);
    // fdmprinter's default 2: layer 0 at cool_fan_speed_0, regular from layer 1.
    EXPECT_EQ(fanRatioForLayer(fan("2"), 0), 0.0);
    EXPECT_EQ(fanRatioForLayer(fan("2"), 1), 1.0);
}

TEST(PathOrderFanRatio, DisabledFanIsOff) {
    EXPECT_EQ(fanRatioForLayer(fan("4", "False"), 0), 0.0);
    EXPECT_EQ(fanRatioForLayer(fan("4", "False"), 10), 0.0);
}

// BUG (engine/planning/PrintPlanner.cpp, fanRatioForLayer: `std::max(1, full_layer - 1)`):
// with cool_fan_full_layer = 1 (the definition's minimum) CuraEngine 4.13 prints layer 0 at the
// regular speed — /usr/bin/CuraEngine with cool_fan_full_layer=1, cool_fan_speed_min=50 writes
// "M106 S127.5" on ;LAYER:0 — but MixEngine returns cool_fan_speed_0 (here 0) for layer 0.
TEST(PathOrderFanRatio, FullLayerOneMeansRegularSpeedFromTheFirstLayer) {
    EXPECT_EQ(fanRatioForLayer(fan("1"), 0), 1.0);
}

}  // namespace
}  // namespace mixengine
