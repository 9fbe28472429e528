// Flow-rate compensation (GCodeExport::newExtrusionConfig): CuraEngine 4.13's offset on E, exactly.
#include <gtest/gtest.h>

#include "gcode/GCodeExport.h"

namespace mixengine {
namespace {

ExportParams compensated(bool relative) {
    ExportParams p;
    p.filament_diameter_mm = 1.75;
    p.retraction_amount_mm = 6.5;
    p.retraction_speed_mm_s = 25;
    p.prime_speed_mm_s = 25;
    p.relative_extrusion = relative;
    p.flow_offset_max = 1.0;
    p.flow_offset_factor = 1.0;
    return p;
}

/// A travel, a new feature's line (1 mm³ over 10 mm at 30 mm/s: 3, capped at 1), a travel, a
/// retraction, a travel and a line.
std::string sequence(bool relative) {
    GCodeExport g(compensated(relative));
    g.travel({10'000, 0}, 150);
    g.newExtrusionConfig();
    g.extrude({20'000, 0}, 1.0, 30);  // 1 mm³ = 0.415752 mm of filament
    g.travel({20'000, 10'000}, 150);
    g.retract();
    g.travel({0, 0}, 150);
    g.extrude({10'000, 0}, 1.0, 30);
    return g.text();
}

TEST(FlowRateOffset, AbsoluteWordsRunTheOffsetAheadRetractionsAndPrimesDoNot) {
    EXPECT_EQ(sequence(false),
              "G0 F9000 X10 Y0\n"
              ";FLOW_RATE_COMPENSATED_OFFSET = 1.000000\n"
              "G1 F1800 X20 Y0 E1.41575\n"
              "G0 F9000 X20 Y10 E1.41575\n"
              "G1 F1500 E-6.08425\n"
              "G0 F9000 X0 Y0 E-5.08425\n"
              "G1 F1500 E0.41575\n"
              "G1 F1800 X10 Y0 E1.8315\n");
}

TEST(FlowRateOffset, RelativeWordsAddTheOffsetToEveryExtrusionAndTravel) {
    EXPECT_EQ(sequence(true),
              "G0 F9000 X10 Y0\n"
              ";FLOW_RATE_COMPENSATED_OFFSET = 1.000000\n"
              "G1 F1800 X20 Y0 E1.41575\n"
              "G0 F9000 X20 Y10 E1\n"
              "G1 F1500 E-6.5\n"
              "G0 F9000 X0 Y0 E1\n"
              "G1 F1500 E6.5\n"
              "G1 F1800 X10 Y0 E1.41575\n");
}

TEST(FlowRateOffset, NothingWithoutAMaximum) {
    ExportParams p = compensated(false);
    p.flow_offset_max = 0;
    GCodeExport g(p);
    g.newExtrusionConfig();
    g.extrude({10'000, 0}, 1.0, 30);
    g.travel({0, 0}, 150);
    EXPECT_EQ(g.text(), "G1 F1800 X10 Y0 E0.41575\nG0 F9000 X0 Y0\n");
}

// MixEngine resets E at each layer start (G92 E0) where CuraEngine does not: the offset already run ahead
// must not be added a second time after the reset, or each layer would push it out again.
TEST(FlowRateOffset, AResetKeepsTheOffsetItDoesNotAddItAgain) {
    GCodeExport g(compensated(false));
    g.newExtrusionConfig();
    g.extrude({10'000, 0}, 1.0, 30);
    g.resetExtrusionAxis();
    g.extrude({20'000, 0}, 1.0, 30);
    EXPECT_EQ(g.text(),
              ";FLOW_RATE_COMPENSATED_OFFSET = 1.000000\n"
              "G1 F1800 X10 Y0 E1.41575\n"
              "G92 E0\n"
              "G1 X20 Y0 E0.41575\n");
}

}  // namespace
}  // namespace mixengine
