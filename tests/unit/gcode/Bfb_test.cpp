// Bits From Bytes output (gcode/Bfb.h): the motor commands around extrusion and travel, the move line,
// the auto-retraction lines and the CR LF line ends, against CuraEngine 4.13's output for the Ender-3
// (1.75 mm filament) with machine_gcode_flavor=BFB.
#include "gcode/Bfb.h"

#include <gtest/gtest.h>

#include <numbers>

#include "gcode/GCodeExport.h"

namespace mixengine {
namespace {

/// Filament mm per mm of a 0.4 × 0.2 mm line with 1.75 mm filament.
double skirtFilamentPerMm() {
    return 0.4 * 0.2 / (std::numbers::pi * 0.875 * 0.875);
}

TEST(Bfb, MotorStartsWithItsSpeedAfterAStopAndStopsBeforeTravel) {
    BfbMotor motor;
    std::string lines;
    EXPECT_EQ(motor.stop(), "M103\n");  // the motor counts as running at the start, as in CuraEngine
    EXPECT_EQ(motor.stop(), "");
    // CuraEngine's first skirt line at 20 mm/s: "M108 S10", "M101", then F1199.8 (rpm 9.98 / 9.98).
    const double feedrate = motor.extrude(skirtFilamentPerMm(), 20, 0, lines);
    EXPECT_EQ(lines, "M108 S10\nM101\n");
    EXPECT_EQ(bfbMove({100'399, 104'315}, 200, feedrate), "G1 X100.399 Y104.315 Z0.2 F1199.8");
    lines.clear();
    motor.extrude(skirtFilamentPerMm(), 20, 0, lines);  // running: nothing to say
    EXPECT_EQ(lines, "");
    EXPECT_EQ(motor.stop(), "M103\n");
    motor.extrude(skirtFilamentPerMm(), 20, 1, lines);  // same RPM: no M108; the second extruder is M201
    EXPECT_EQ(lines, "M201\n");
    EXPECT_EQ(motor.prime(), "");  // running: no firmware prime
    EXPECT_EQ(motor.stop(), "M103\n");
    EXPECT_EQ(motor.prime(), "G11\n");
    EXPECT_EQ(motor.stop(), "M103\n");  // after G11 it counts as running again
}

TEST(Bfb, AutoRetractionAndLineEnds) {
    EXPECT_EQ(bfbAutoRetraction(6'500, true), ";enable auto-retraction\nM227 S16640 P16640\nG92 E0\n");
    EXPECT_EQ(bfbAutoRetraction(5'000, false), ";enable auto-retraction\nM227 S12800 P12800\n");
    const std::string user = "G28 ;home\nG1 Z5\n";
    EXPECT_EQ(withBfbLineEnds("M82\n" + user + "\nM104 S0\n", {user}),
              "M82\r\nG28 ;home\nG1 Z5\n\r\nM104 S0\r\n");
    EXPECT_EQ(withBfbLineEnds("A\nB\n", {"A"}), "A\r\nB\r\n");  // a one-line block keeps nothing
}

TEST(Bfb, ExportWritesNoEWordsAndCarriesZOnTheNextMove) {
    ExportParams p;
    p.flavor = flavorTraits(Flavor::Bfb);
    p.firmware_retract = true;
    p.filament_diameter_mm = 1.75;
    GCodeExport gcode(p);
    gcode.startLayer(200, 5);
    gcode.travel({1'000, 0}, 150);
    gcode.retract();  // the firmware retracts by itself: nothing written
    gcode.primeInPlace();
    gcode.extrude({11'000, 0}, 0.8, 20);  // 10 mm of a 0.4 × 0.2 mm line
    gcode.travel({11'000, 5'000}, 150);
    EXPECT_EQ(gcode.text(),
              "M103\nG1 X1 Y0 Z0.2 F9000\nG11\nG1 X11 Y0 Z0.2 F1199.8\nM103\nG1 X11 Y5 Z0.2 F9000\n");
}

}  // namespace
}  // namespace mixengine
