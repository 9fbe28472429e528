// The wipe script between layers (gcode/WipeScript.h): CuraEngine 4.13's sequence, exactly.
#include "gcode/WipeScript.h"

#include <gtest/gtest.h>

#include <string>

namespace mixengine {
namespace {

ExportParams marlin175() {
    ExportParams p;
    p.filament_diameter_mm = 1.75;
    return p;
}

WipeScriptConfig config() {
    WipeScriptConfig w;
    w.retraction = {2.0, 30, 20, 0};
    w.hop_enable = true;
    w.hop_um = 1'000;
    w.hop_speed_mm_s = 5;
    w.brush_x_um = 100'000;
    w.repeat_count = 3;
    w.move_distance_um = 20'000;
    w.move_speed_mm_s = 150;
    w.pause_s = 0.5;
    return w;
}

TEST(WipeScript, RetractLiftBrushBackLowerPrimePause) {
    GCodeExport g(marlin175());
    g.moveZ(200, 10);
    g.travel({10'000, 20'000}, 150);
    g.takeText();
    writeWipeScript(config(), g);
    EXPECT_EQ(g.text(),
              ";WIPE_SCRIPT_BEGIN\n"
              "G1 F1800 E-2\n"
              "G1 F300 Z1.2\n"
              "G0 F9000 X100 Y20\n"
              "G0 X120 Y20\n"
              "G0 X100 Y20\n"
              "G0 X120 Y20\n"
              "G0 X10 Y20\n"
              "G1 F300 Z0.2\n"
              "G1 F1200 E0\n"
              "G4 P500\n"
              ";WIPE_SCRIPT_END\n");
    EXPECT_FALSE(g.retracted());
}

TEST(WipeScript, WithoutRetractionHopOrPauseOnlyTheBrushMoves) {
    GCodeExport g(marlin175());
    g.travel({10'000, 20'000}, 150);
    g.takeText();
    WipeScriptConfig w = config();
    w.retraction_enable = false;
    w.hop_enable = false;
    w.pause_s = 0;
    w.repeat_count = 1;
    writeWipeScript(w, g);
    EXPECT_EQ(g.text(),
              ";WIPE_SCRIPT_BEGIN\n"
              "G0 X100 Y20\n"
              "G0 X120 Y20\n"
              "G0 X10 Y20\n"
              ";WIPE_SCRIPT_END\n");
}

TEST(WipeScript, TheExtraPrimeIsPrimedAtTheEnd) {
    GCodeExport g(marlin175());
    g.travel({10'000, 20'000}, 150);
    g.takeText();
    WipeScriptConfig w = config();
    w.hop_enable = false;
    w.pause_s = 0;
    w.repeat_count = 0;
    w.retraction.extra_prime_mm3 = 2.405281875;  // 1 mm of 1.75 mm filament
    writeWipeScript(w, g);
    EXPECT_NE(g.text().find("G1 F1200 E1\n"), std::string::npos) << g.text();
}

}  // namespace
}  // namespace mixengine
