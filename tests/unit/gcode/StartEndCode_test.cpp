// Start and end G-code (gcode/StartEndCode.h). The expected temperature lines are those of
// /usr/bin/CuraEngine 4.13 (FffGcodeWriter::processInitialLayerTemperature), checked by slicing a
// cube with the flags below.
#include "gcode/StartEndCode.h"

#include <gtest/gtest.h>

#include "../SettingsTestSupport.h"

namespace mixengine {
namespace {

constexpr const char* kM82 = "M82 ;absolute extrusion mode\n";
constexpr const char* kM83 = "M83 ;relative extrusion mode\n";

SettingValues globalValues() {
    return {{"machine_heated_bed", "True"},
            {"material_bed_temp_prepend", "True"},
            {"material_bed_temp_wait", "True"},
            {"material_bed_temperature_layer_0", "60"},
            {"material_print_temp_prepend", "True"},
            {"material_print_temp_wait", "True"},
            {"machine_gcode_flavor", "RepRap (Marlin/Sprinter)"},
            {"machine_depth", "235"},
            {"machine_start_gcode", "G28 ;Home\nG1 Y{machine_depth} ;{print_time}"},
            {"machine_end_gcode", "M84"}};
}

Settings global(const SettingValues& changes = {}) {
    return test::defaultsWith("global settings", globalValues()).with("global settings", changes);
}

Settings extruder0(const char* layer0 = "215", const char* print = "200") {
    return test::defaultsWith("extruder 0", {{"material_print_temperature_layer_0", layer0},
                                             {"material_print_temperature", print}});
}

/// The flavor row of the settings' machine_gcode_flavor (gcode/OutputParams reads it so).
const FlavorTraits& flavorIn(const Settings& g) {
    return flavorOf(g.text(key::machine_gcode_flavor));
}

// Tokens were expanded before (by Cura, or settings/FrontendValues): startCode keeps them verbatim.
const std::string kStart = "G28 ;Home\nG1 Y{machine_depth} ;{print_time}\n";

TEST(GCodeStartEndCode, WaitForBedAndNozzle) {
    EXPECT_EQ(startCode(global(), flavorIn(global()), extruder0(), false),
              "M140 S60\nM105\nM190 S60\nM104 S215\nM105\nM109 S215\n" + std::string(kM82) + kStart);
}

TEST(GCodeStartEndCode, NoPrependNoTemperatureLines) {
    const Settings g =
        global({{"material_bed_temp_prepend", "False"}, {"material_print_temp_prepend", "False"}});
    EXPECT_EQ(startCode(g, flavorIn(g), extruder0(), false), kM82 + kStart);
}

TEST(GCodeStartEndCode, UnheatedBedGetsNoBedLines) {
    const Settings g = global({{"machine_heated_bed", "False"}});
    EXPECT_EQ(startCode(g, flavorIn(g), extruder0("212.5"), false),
              "M104 S212.5\nM105\nM109 S212.5\n" + std::string(kM82) + kStart);
}

TEST(GCodeStartEndCode, RelativeExtrusionSwitchesAfterTheStartCode) {
    const Settings g =
        global({{"material_bed_temp_prepend", "False"}, {"material_print_temp_prepend", "False"}});
    EXPECT_EQ(startCode(g, flavorIn(g), extruder0(), true), kM82 + kStart + kM83);
    EXPECT_EQ(endCode(g, flavorIn(g), true), std::string(kM82) + "M84\n" + kM82);
}

TEST(GCodeStartEndCode, CodeIsWrittenVerbatim) {
    const Settings g = global({{"material_bed_temp_prepend", "False"},
                               {"material_print_temp_prepend", "False"},
                               {"machine_end_gcode", "G1 X{machine_depth}\nM84 ;{jobname}"}});
    EXPECT_EQ(endCode(g, flavorIn(g), false).rfind("G1 X{machine_depth}\nM84 ;{jobname}\n", 0), 0U)
        << endCode(g, flavorIn(g), false);
    EXPECT_NE(startCode(g, flavorIn(g), extruder0(), false).find("G1 Y{machine_depth} ;{print_time}\n"),
              std::string::npos);
}

// As CuraEngine (writeCode: the code, then a line end): a block ending in a line end is followed by an
// empty line (the oracle's Ender-3 end code shows it).
TEST(GCodeStartEndCode, StartCodeEndingInNewlineGetsABlankLine) {
    const Settings g = global({{"material_bed_temp_prepend", "False"},
                               {"material_print_temp_prepend", "False"},
                               {"machine_start_gcode", "G28\n"}});
    EXPECT_EQ(startCode(g, flavorIn(g), extruder0(), false), std::string(kM82) + "G28\n\n");
}

// BUG (engine/gcode/StartEndCode.cpp, startCode: `appendLine(out, "M105")` after M140 and after M104
// unconditionally): CuraEngine writes M105 only as part of the wait sequence (Marlin:
// "M140 S60 / M105 / M190 S60", "M105 / M109 S215"). With material_bed_temp_wait=False and
// material_print_temp_wait=False /usr/bin/CuraEngine writes just "M140 S60\nM104 S215\n".
TEST(GCodeStartEndCode, NoM105WithoutWaiting) {
    const Settings no_wait =
        global({{"material_bed_temp_wait", "False"}, {"material_print_temp_wait", "False"}});
    EXPECT_EQ(startCode(no_wait, flavorIn(no_wait), extruder0(), false),
              "M140 S60\nM104 S215\n" + std::string(kM82) + kStart);
    const Settings bed_wait = global({{"material_print_temp_wait", "False"}});
    EXPECT_EQ(startCode(bed_wait, flavorIn(bed_wait), extruder0(), false),
              "M140 S60\nM105\nM190 S60\nM104 S215\n" + std::string(kM82) + kStart);
}

// BUG (engine/gcode/StartEndCode.cpp, startCode): CuraEngine skips the bed lines when
// material_bed_temperature_layer_0 is 0 and uses material_print_temperature when
// material_print_temperature_layer_0 is 0 (checked: "M104 S205 / M105 / M109 S205", no M140/M190).
// MixEngine writes "M140 S0 ... M190 S0" and "M104 S0 ... M109 S0".
TEST(GCodeStartEndCode, ZeroInitialTemperaturesLikeCuraEngine) {
    const Settings g = global({{"material_bed_temperature_layer_0", "0"}});
    EXPECT_EQ(startCode(g, flavorIn(g), extruder0("0", "205"), false),
              "M104 S205\nM105\nM109 S205\n" + std::string(kM82) + kStart);
}

// BUG (engine/gcode/StartEndCode.cpp, endCode): CuraEngine always sets the extrusion mode after the
// end code — "M82 ;absolute extrusion mode" (Marlin), "M83 ;relative extrusion mode" for
// RepRap (RepRap) — also without relative_extrusion. MixEngine writes it only when relative.
TEST(GCodeStartEndCode, EndCodeRestoresTheExtrusionModeLikeCuraEngine) {
    EXPECT_EQ(endCode(global(), flavorIn(global()), false), "M84\n" + std::string(kM82));
    const Settings reprap = global({{"machine_gcode_flavor", "RepRap (RepRap)"}});
    EXPECT_EQ(endCode(reprap, flavorIn(reprap), false), "M84\n" + std::string(kM83));
}

// For RepRap (RepRap) CuraEngine writes "T0" first, no "M140" before "M190" and no "M105" lines (observed:
// "T0 / M190 S60 / M104 S212.5 / M109 S212.5").
TEST(GCodeStartEndCode, RepRapFlavourTemperatureLinesLikeCuraEngine) {
    const Settings reprap = global({{"machine_gcode_flavor", "RepRap (RepRap)"}});
    EXPECT_EQ(startCode(reprap, flavorIn(reprap), extruder0("212.5"), false),
              "T0\nM190 S60\nM104 S212.5\nM109 S212.5\n" + std::string(kM82) + kStart);
}

// Griffin (observed with /usr/bin/CuraEngine): "T0", no prepended temperatures, the machine's start
// code, then "M109 S<initial temperature>".
TEST(GCodeStartEndCode, GriffinWaitsForTheNozzleAfterTheStartCode) {
    const Settings griffin = global({{"machine_gcode_flavor", "Griffin"}});
    EXPECT_EQ(startCode(griffin, flavorIn(griffin), extruder0("212.5"), false),
              "T0\n" + std::string(kM82) + kStart + "M109 S212.5\n");
}

TEST(GCodeStartEndCode, UltiGCodeHasNoTemperatureLines) {
    const Settings ulti = global({{"machine_gcode_flavor", "UltiGCode"}});
    EXPECT_EQ(startCode(ulti, flavorIn(ulti), extruder0("212.5"), false), std::string(kM82) + kStart);
}

}  // namespace
}  // namespace mixengine

namespace mixengine {
namespace {

ExportParams s5Export(Flavor flavor = Flavor::Griffin) {
    ExportParams p;
    p.filament_diameter_mm = 2.85;
    p.retraction_speed_mm_s = 25;
    p.prime_speed_mm_s = 25;
    p.flavor = flavorTraits(flavor);
    p.retraction_amount_mm = 6.5;
    p.retraction_hop_um = 2000;  // the prime's retraction does not hop
    return p;
}

// Griffin without a prime blob: `G280 S1`, Z written again, the retraction (CuraEngine's start on the
// Ultimaker S5); only once per extruder.
TEST(GCodeStartEndCode, PrimeTrainOnGriffinWithoutBlob) {
    GCodeExport g(s5Export());
    g.moveZ(200, 10);
    g.takeText();
    writePrimeTrain(PrimeTrain{}, g);
    EXPECT_EQ(g.takeText(), "G280 S1\nG0 Z0.2\nG1 F1500 E-6.5\n");
    writePrimeTrain(PrimeTrain{}, g);
    EXPECT_EQ(g.takeText(), "");
}

// prime_blob_enable: a travel to the prime position first, then `G280`; other flavors only travel and
// retract.
TEST(GCodeStartEndCode, PrimeBlobTravelsToThePrimePosition) {
    GCodeExport g(s5Export());
    writePrimeTrain({true, {333'000, 6'000}, true, 150}, g);
    EXPECT_EQ(g.takeText(), "G0 F9000 X333 Y6\nG280\nG1 F1500 E-6.5\n");
    GCodeExport marlin(s5Export(Flavor::Marlin));
    writePrimeTrain({true, {5'000, 0}, false, 150}, marlin);
    EXPECT_EQ(marlin.takeText(), "G0 F9000 X5 Y0\nG1 F1500 E-6.5\n");
}

// machine_extruders_share_nozzle: every filament is primed by the start code and pulled back by the
// initial retraction; the first retraction takes only the rest.
TEST(GCodeStartEndCode, SharedNozzleStartsPrimedAndPartlyRetracted) {
    GCodeExport g(s5Export());
    g.assumePrimed(0, 1.0);
    writePrimeTrain(PrimeTrain{}, g);
    EXPECT_EQ(g.takeText(), "G1 F1500 E-5.5\n");
}

}  // namespace
}  // namespace mixengine
