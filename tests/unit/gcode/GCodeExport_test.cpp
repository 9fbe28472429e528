// The G-code writer core (gcode/GCodeExport.h): exact text for short move sequences.
#include "gcode/GCodeExport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace mixengine {
namespace {

ExportParams marlin175() {
    ExportParams p;
    p.filament_diameter_mm = 1.75;
    p.retraction_amount_mm = 6.5;
    p.retraction_speed_mm_s = 25;
    p.prime_speed_mm_s = 25;
    p.z_hop_speed_mm_s = 10;
    return p;
}

TEST(GCodeExport, AbsoluteSequence) {
    GCodeExport g(marlin175());
    g.travel({10'000, 20'000}, 150);
    g.travel({10'000, 20'000}, 150);       // already there: nothing
    g.extrude({20'000, 20'000}, 1.0, 30);  // 1 mm³ / (π·0.875²) = 0.415752 mm
    g.extrude({20'000, 30'000}, 1.0, 30);  // feedrate unchanged: no F
    g.retract();
    g.retract();  // already retracted: nothing
    g.travel({0, 0}, 150);
    g.extrude({10'000, 0}, 1.0, 30);  // primes first
    g.setFan(1.0);
    g.setFan(1.0);
    g.setFan(0.0);
    g.moveZ(300, 10);
    g.comment("TYPE:FILL");
    g.resetExtrusionAxis();
    g.line("M84");
    EXPECT_EQ(g.text(),
              "G0 F9000 X10 Y20\n"
              "G1 F1800 X20 Y20 E0.41575\n"
              "G1 X20 Y30 E0.8315\n"
              "G1 F1500 E-5.6685\n"
              "G0 F9000 X0 Y0\n"
              "G1 F1500 E0.8315\n"
              "G1 F1800 X10 Y0 E1.24726\n"
              "M106 S255\n"
              "M107\n"
              "G0 F600 Z0.3\n"
              ";TYPE:FILL\n"
              "G92 E0\n"
              "M84\n");
    EXPECT_NEAR(g.totalExtruded(), 3.0 / (std::numbers::pi * 0.875 * 0.875), 1e-12);
    EXPECT_EQ(g.z(), 300);
    EXPECT_FALSE(g.retracted());
}

// MACH3 (CuraEngine's extruderCharacter): extruder n's axis is 'A' + n in moves, retractions and resets.
TEST(GCodeExport, Mach3WritesTheAAxisPerExtruder) {
    ExportParams p = marlin175();
    p.flavor = flavorTraits(Flavor::Mach3);
    GCodeExport g(p);
    g.extrude({20'000, 0}, 1.0, 30);
    g.retract();
    g.resetExtrusionAxis();
    ToolChange change;
    change.extruder = 1;
    change.filament_diameter_mm = 1.75;
    g.selectExtruder(change);
    g.extrude({0, 0}, 1.0, 30);
    EXPECT_EQ(g.text(),
              "G1 F1800 X20 Y0 A0.41575\nG1 F1500 A-6.08425\nG92 A0\nT1\nG92 B0\nG1 F1800 X0 Y0 B0.41575\n");
}

TEST(GCodeExport, RelativeSequence) {
    ExportParams p = marlin175();
    p.relative_extrusion = true;
    GCodeExport g(p);
    g.extrude({10'000, 0}, 1.0, 30);
    g.retract();
    EXPECT_TRUE(g.retracted());
    g.travel({10'000, 10'000}, 150);
    g.extrude({0, 10'000}, 1.0, 30);
    g.resetExtrusionAxis();  // relative: nothing
    EXPECT_EQ(g.text(),
              "G1 F1800 X10 Y0 E0.41575\n"
              "G1 F1500 E-6.5\n"
              "G0 F9000 X10 Y10\n"
              "G1 F1500 E6.5\n"
              "G1 F1800 X0 Y10 E0.41575\n");
}

TEST(GCodeExport, VolumetricExtrusionInCubicMillimetres) {
    ExportParams p = marlin175();
    p.flavor = flavorTraits(Flavor::MarlinVolumetric);
    GCodeExport g(p);
    g.extrude({10'000, 0}, 1.5, 30);
    g.extrude({20'000, 0}, 0.25, 30);
    EXPECT_EQ(g.text(), "G1 F1800 X10 Y0 E1.5\nG1 X20 Y0 E1.75\n");
    EXPECT_EQ(g.totalExtruded(), 1.75);
}

// BUG (engine/gcode/GCodeExport.cpp, retract()/unretract(): `axis_.move(-params_.retraction_amount_mm)`):
// in volumetric mode the E axis is in mm³, but the retraction amount (mm of filament) is written
// unconverted. CuraEngine 4.13 with RepRap (Volumetric) and 2.85 mm filament retracts
// "G1 F1500 E-41.46608" (6.5 mm × π·1.425² mm²); MixEngine writes 6.5 mm³.
TEST(GCodeExport, VolumetricRetractionIsConvertedToCubicMillimetres) {
    ExportParams p = marlin175();
    p.flavor = flavorTraits(Flavor::MarlinVolumetric);
    p.filament_diameter_mm = 2.85;
    GCodeExport g(p);
    g.extrude({10'000, 0}, 10.0, 30);
    g.retract();
    g.unretract();
    EXPECT_EQ(g.text(), "G1 F1800 X10 Y0 E10\nG1 F1500 E-31.46608\nG1 E10\n");
}

TEST(GCodeExport, RetractionHopLiftsAndLowers) {
    ExportParams p = marlin175();
    p.retraction_hop_um = 200;
    GCodeExport g(p);
    g.moveZ(300, 10);
    g.retract();
    EXPECT_EQ(g.z(), 500);
    g.travel({5'000, 0}, 150);
    g.extrude({6'000, 0}, 0.0, 25);
    EXPECT_EQ(g.z(), 300);
    // Order: retract, lift, travel, lower, prime, extrude (the Z-move feedrates are not fixed here).
    const std::string& t = g.text();
    const auto retract = t.find("G1 F1500 E-6.5\n");
    const auto lift = t.find(" Z0.5\n");
    const auto travel = t.find("G0 F9000 X5 Y0\n");
    const auto lower = t.find(" Z0.3\n", travel);
    const auto prime = t.find(" E0\n", lower);
    const auto extrude = t.find("G1 X6 Y0 E0\n");
    ASSERT_NE(extrude, std::string::npos) << t;
    EXPECT_LT(retract, lift) << t;
    EXPECT_LT(lift, travel) << t;
    EXPECT_LT(travel, lower) << t;
    EXPECT_LT(lower, prime) << t;
    EXPECT_LT(prime, extrude) << t;
}

TEST(GCodeExport, ExtraPrimeAfterEachRetractionButNotAfterASwitch) {
    ExportParams p = marlin175();
    p.retraction_extra_prime_mm3 = 1.0;  // 0.415752 mm of 1.75 mm filament
    GCodeExport g(p);
    g.extrude({10'000, 0}, 1.0, 30);
    g.retract();
    g.travel({0, 0}, 150);
    g.extrude({10'000, 0}, 1.0, 30);  // primes 6.5 mm back plus the extra 1 mm³ in one move, as CuraEngine
    EXPECT_EQ(g.text(),
              "G1 F1800 X10 Y0 E0.41575\n"
              "G1 F1500 E-6.08425\n"
              "G0 F9000 X0 Y0\n"
              "G1 F1500 E0.8315\n"
              "G1 F1800 X10 Y0 E1.24726\n");
    EXPECT_NEAR(g.totalExtruded(), 3.0 / (std::numbers::pi * 0.875 * 0.875), 1e-12);  // the extra counts
    ToolChange change;
    change.extruder = 1;
    change.filament_diameter_mm = 1.75;
    g.selectExtruder(change);  // the switch retraction is the planner's; a switch primes nothing extra
    const std::size_t before = g.text().size();
    g.extrude({0, 0}, 1.0, 30);
    EXPECT_EQ(g.text().substr(before), "G1 X0 Y0 E0.41575\n");  // no prime, extra or not
}

TEST(GCodeExport, DwellInMillisecondsCountsInTheTime) {
    GCodeExport g(marlin175());
    g.dwell(1.25);
    EXPECT_EQ(g.text(), "G4 P1250\n");
    EXPECT_NEAR(g.elapsedSeconds(), 1.25, 1e-12);
}

TEST(GCodeExport, NoRetractionWhenAmountIsZero) {
    ExportParams p = marlin175();
    p.retraction_amount_mm = 0;
    GCodeExport g(p);
    g.retract();
    EXPECT_EQ(g.text(), "");
    EXPECT_FALSE(g.retracted());
}

/// Marlin, 1.75 mm, with acceleration and jerk out of the way: every move takes distance / speed.
ExportParams withoutAccelerationOrJerk() {
    ExportParams p = marlin175();
    p.kinematics.acceleration_mm_s2 = 1e12;
    p.kinematics.max_acceleration_mm_s2 = {1e12, 1e12, 1e12, 1e12};
    p.kinematics.jerk_xy_mm_s = p.kinematics.jerk_z_mm_s = p.kinematics.jerk_e_mm_s = 1e9;
    return p;
}

// The acceleration model itself is tested in TimeEstimate_test.cpp.
TEST(GCodeExport, ElapsedTimeFromDistanceAndSpeed) {
    GCodeExport g(withoutAccelerationOrJerk());
    g.travel({30'000, 40'000}, 50);   // 50 mm at 50 mm/s: 1 s
    g.extrude({30'000, 0}, 1.0, 20);  // 40 mm at 20 mm/s: 2 s
    g.retract();                      // 6.5 mm at 25 mm/s: 0.26 s
    g.unretract();                    // 0.26 s
    g.moveZ(2'000, 10);               // 2 mm at 10 mm/s: 0.2 s
    EXPECT_NEAR(g.elapsedSeconds(), 3.72, 1e-6);
    g.takeText();
    EXPECT_EQ(g.text(), "");
}

// Each move's time goes to what it prints (CuraEngine's PrintFeatureType buckets): extrusions to the
// feature set last, travel to Travel, retractions, primes and travel while retracted to Retraction.
TEST(GCodeExport, TimeIsBookedByFeature) {
    GCodeExport g(withoutAccelerationOrJerk());
    g.travel({30'000, 40'000}, 50);  // 1 s of travel
    g.setTimeFeature(TimeFeature::OuterWall);
    g.extrude({30'000, 0}, 1.0, 20);  // 2 s of outer wall
    g.retract();                      // 0.26 s
    g.travel({0, 0}, 30);             // 1 s, retracted
    g.setTimeFeature(TimeFeature::Infill);
    g.extrude({0, 10'000}, 0.5, 10);  // prime 0.26 s, then 1 s of infill
    const FeatureSeconds s = g.secondsByFeature();
    const auto at = [&s](TimeFeature f) { return s[static_cast<std::size_t>(f)]; };
    EXPECT_NEAR(at(TimeFeature::Travel), 1.0, 1e-6);
    EXPECT_NEAR(at(TimeFeature::OuterWall), 2.0, 1e-6);
    EXPECT_NEAR(at(TimeFeature::Retraction), 0.26 + 1.0 + 0.26, 1e-6);
    EXPECT_NEAR(at(TimeFeature::Infill), 1.0, 1e-6);
    EXPECT_NEAR(at(TimeFeature::None), 0.0, 1e-12);
    EXPECT_NEAR(g.elapsedSeconds(), 5.52, 1e-6);
}

// The estimate's E axis is mm of filament in every flavor, as CuraEngine's (it converts E to mm
// before planning) and as the firmware's E limits are meant: a volumetric print of the same moves
// takes the same time. Here the E feedrate limit bites only if E were counted in mm³ (1 mm³ over
// 40 mm at 20 mm/s: 0.21 mm/s of 1.75 mm filament, 0.5 mm³/s).
TEST(GCodeExport, VolumetricTimeEstimateCountsMillimetresOfFilament) {
    for (const bool volumetric : {false, true}) {
        ExportParams p = marlin175();
        p.flavor = flavorTraits(volumetric ? Flavor::MarlinVolumetric : Flavor::Marlin);
        p.kinematics.acceleration_mm_s2 = 1e12;
        p.kinematics.max_acceleration_mm_s2 = {1e12, 1e12, 1e12, 1e12};
        p.kinematics.jerk_xy_mm_s = p.kinematics.jerk_z_mm_s = p.kinematics.jerk_e_mm_s = 1e9;
        p.kinematics.max_feedrate_mm_s[3] = 0.3;
        GCodeExport g(p);
        g.extrude({40'000, 0}, 1.0, 20);  // 40 mm at 20 mm/s: 2 s
        EXPECT_NEAR(g.elapsedSeconds(), 2.0, 1e-6) << (volumetric ? "volumetric" : "mm");
    }
}

// CuraEngine 4.13 writes the fan as `PrecisionedDouble{1, percent * 255 / 100}`: 50 % → "M106 S127.5"
// (checked with /usr/bin/CuraEngine, cool_fan_speed_min=50). BUG (engine/gcode/GCodeExport.cpp,
// setFan(): `std::lround(ratio * 255)`) writes "M106 S128".
TEST(GCodeExport, FanSpeedKeepsOneDecimalLikeCuraEngine) {
    GCodeExport g(marlin175());
    g.setFan(0.5);
    g.setFan(0.3);
    EXPECT_EQ(g.text(), "M106 S127.5\nM106 S76.5\n");
}

}  // namespace
}  // namespace mixengine

namespace mixengine {
namespace {

// CuraEngine's retraction model: a longer retraction retracts the difference, a shorter one primes the
// difference back at the speed of the one before, the extra prime of each retraction is primed at the next
// unretraction (and counted as filament of that extruder).
TEST(GCodeExport, RetractToChangesTheRetractedAmountBothWays) {
    ExportParams p = marlin175();
    p.prime_speed_mm_s = 15;
    GCodeExport g(p);
    g.retract();                      // 6.5 mm at 25 mm/s
    g.retractTo({8.0, 20, 15, 0});    // a switch retraction: 1.5 mm more at 20 mm/s
    g.retractTo({8.0, 20, 15, 0});    // nothing
    g.retractTo({6.5, 25, 25, 1.0});  // primes 1.5 mm at the switch's 15 mm/s, owes 1 mm³ more
    g.unretract();                    // 6.5 mm + 1 mm³ (0.41575 mm) at 25 mm/s
    EXPECT_EQ(g.text(), "G1 F1500 E-6.5\nG1 F1200 E-8\nG1 F900 E-6.5\nG1 F1500 E0.41575\n");
    EXPECT_NEAR(g.filamentPerExtruder().at(0), 0.41575, 1e-4);
}

// The z-hop of a switch is written again when the nozzle is up already; back down before extruding.
TEST(GCodeExport, HopRewrittenOnRequestAndLoweredBeforeExtruding) {
    ExportParams p = marlin175();
    p.retraction_hop_um = 2000;
    GCodeExport g(p);
    g.moveZ(200, 10);
    g.retract();
    g.hopTo(2000);        // up already: nothing
    g.hopTo(2000, true);  // the line again
    g.extrude({1'000, 0}, 0.0, 20);
    EXPECT_EQ(g.text(),
              "G0 F600 Z0.2\nG1 F1500 E-6.5\nG1 F600 Z2.2\nG1 F600 Z2.2\nG1 F600 Z0.2\nG1 F1500 E0\nG1 F1200 "
              "X1 Y0 E0\n");
}

// Each extruder's fan: P<n> when it is not fan 0, and the speed written again after a switch to another fan.
TEST(GCodeExport, FanOfTheActiveExtruder) {
    GCodeExport g(marlin175());
    g.setFan(1.0);
    ToolChange change;
    change.extruder = 1;
    change.fan_number = 1;
    g.selectExtruder(change);
    g.setFan(1.0);
    g.setFan(0.0);
    EXPECT_EQ(g.text(), "M106 S255\nT1\nG92 E0\nM106 S255 P1\nM107 P1\n");
}

}  // namespace
}  // namespace mixengine
