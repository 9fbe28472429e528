// The flavor table (gcode/Flavor.h): every option of Cura's machine_gcode_flavor, read from the
// installed fdmprinter.def.json, is a flavor of its own; any other text is Unknown (no error, as
// the engine always did); and a few facts of each row, as CuraEngine 4.13 writes them.
#include "gcode/Flavor.h"

#include <gtest/gtest.h>

#include <set>

#include "settings/DefinitionSet.h"

namespace mixengine {
namespace {

const std::filesystem::path kCura = "/usr/share/cura/resources";

std::vector<std::string> curaFlavorOptions() {
    const DefinitionSet set = loadDefinitionSet("fdmprinter", {kCura / "definitions", kCura / "extruders"});
    const SettingDefinition* flavor = set.find("machine_gcode_flavor");
    return flavor ? flavor->enum_options : std::vector<std::string>{};
}

TEST(Flavor, EveryCuraOptionIsAFlavorOfItsOwn) {
    const std::vector<std::string> options = curaFlavorOptions();
    ASSERT_EQ(options.size(), 9U);
    std::set<Flavor> seen;
    for (const std::string& option : options) {
        const Flavor flavor = parseFlavor(option);
        EXPECT_NE(flavor, Flavor::Unknown) << option;
        EXPECT_EQ(flavorTraits(flavor).setting, option);
        EXPECT_EQ(&flavorOf(option), &flavorTraits(flavor));
        seen.insert(flavor);
    }
    EXPECT_EQ(seen.size(), options.size());
}

TEST(Flavor, EveryFlavorHasItsRow) {
    for (const Flavor flavor :
         {Flavor::Marlin, Flavor::MarlinVolumetric, Flavor::RepRap, Flavor::UltiGCode, Flavor::Griffin,
          Flavor::Makerbot, Flavor::Bfb, Flavor::Mach3, Flavor::Repetier, Flavor::Unknown})
        EXPECT_EQ(flavorTraits(flavor).flavor, flavor);
}

// Any other text, such as a machine definition's "MakerBot", is Unknown: Marlin's header and
// commands without Marlin's temperature waits — what the engine wrote before the table existed.
TEST(Flavor, OtherTextIsUnknownWithMarlinsHeader) {
    for (const char* text : {"MakerBot", "marlin", "", " RepRap (Marlin/Sprinter)", "Marlin"})
        EXPECT_EQ(parseFlavor(text), Flavor::Unknown) << '"' << text << '"';
    const FlavorTraits& unknown = flavorOf("MakerBot");
    EXPECT_EQ(unknown.header_name, "Marlin");
    EXPECT_EQ(unknown.header, HeaderStyle::Long);
    EXPECT_FALSE(unknown.m105_before_wait);
    EXPECT_FALSE(unknown.fan_on_off);
    EXPECT_TRUE(flavorOf("RepRap (Marlin/Sprinter)").m105_before_wait);
}

TEST(Flavor, HeadersByFlavor) {
    EXPECT_EQ(flavorOf("Griffin").header, HeaderStyle::Griffin);
    EXPECT_EQ(flavorOf("UltiGCode").header, HeaderStyle::UltiGCode);
    EXPECT_EQ(flavorOf("RepRap (RepRap)").header, HeaderStyle::Long);
    EXPECT_EQ(flavorOf("Repetier").header, HeaderStyle::Short);
    EXPECT_EQ(flavorOf("RepRap (Volumetric)").header_name, "Marlin(Volumetric)");
    EXPECT_EQ(flavorOf("MACH3").header_name, "Mach3");
}

TEST(Flavor, ExtrusionByFlavor) {
    EXPECT_TRUE(flavorOf("RepRap (Volumetric)").volumetric_e);  // E in mm³
    EXPECT_TRUE(flavorOf("UltiGCode").volumetric_e);
    EXPECT_FALSE(flavorOf("RepRap (Marlin/Sprinter)").volumetric_e);
    const FlavorTraits& mach3 = flavorOf("MACH3");
    EXPECT_EQ(mach3.axis, 'A');
    EXPECT_TRUE(mach3.axis_per_extruder);
    const FlavorTraits& bfb = flavorOf("BFB");
    EXPECT_TRUE(bfb.rpm_extrusion && bfb.auto_retraction && bfb.crlf_line_ends);
    EXPECT_FALSE(bfb.resets_e_each_layer);
    EXPECT_TRUE(flavorOf("RepRap (RepRap)").ends_relative);
}

TEST(Flavor, StartCodeByFlavor) {
    const FlavorTraits& griffin = flavorOf("Griffin");
    EXPECT_TRUE(griffin.start_selects_tool && griffin.heats_nozzle_after_start && griffin.firmware_prime);
    EXPECT_FALSE(griffin.prepends_temperatures || griffin.build_volume_temperature);
    const FlavorTraits& ulti = flavorOf("UltiGCode");
    EXPECT_FALSE(ulti.prepends_temperatures || ulti.build_volume_temperature ||
                 ulti.heats_nozzle_after_start);
    EXPECT_TRUE(flavorOf("RepRap (RepRap)").start_selects_tool);
    EXPECT_TRUE(flavorOf("Makerbot").nozzle_wait_m116);
    EXPECT_TRUE(flavorOf("Makerbot").fan_on_off);
}

TEST(Flavor, MotionCommandFormsByFlavor) {
    const MotionForms& marlin = flavorOf("RepRap (Marlin/Sprinter)").motion;
    EXPECT_EQ(marlin.print_acceleration, "M204 S");
    EXPECT_TRUE(marlin.travel_acceleration.empty());
    const MotionForms& reprap = flavorOf("RepRap (RepRap)").motion;
    EXPECT_EQ(reprap.travel_acceleration, "M204 T");
    EXPECT_EQ(reprap.jerk, "M566 X");
    EXPECT_EQ(reprap.jerk_scale, 60);
    const MotionForms& repetier = flavorOf("Repetier").motion;
    EXPECT_EQ(repetier.print_acceleration, "M201 X");
    EXPECT_TRUE(repetier.acceleration_y);
    EXPECT_FALSE(repetier.jerk_y);
}

}  // namespace
}  // namespace mixengine
