// What the writer and the header get from the resolved settings (gcode/OutputParams.h): the
// volume of filament each extruder train used, from millimetres of filament or, in volumetric
// flavors, from cubic millimetres as they are.
#include "gcode/OutputParams.h"

#include <gtest/gtest.h>

#include <numbers>

#include "unit/toolpaths/ToolpathTestSupport.h"

namespace mixengine {
namespace {

ResolvedMachine twoTrains(const std::string& flavor) {
    return test::fdmMachine({{"machine_extruder_count", "2"}, {"machine_gcode_flavor", flavor}},
                            {{0, {{"material_diameter", "1.75"}}}, {1, {{"material_diameter", "2.85"}}}});
}

TEST(OutputParams, ExportParamsAreVolumetricForVolumetricFlavors) {
    EXPECT_FALSE(exportParams(twoTrains("RepRap (Marlin/Sprinter)")).flavor.volumetric_e);
    EXPECT_TRUE(exportParams(twoTrains("RepRap (Volumetric)")).flavor.volumetric_e);
    EXPECT_TRUE(exportParams(twoTrains("UltiGCode")).flavor.volumetric_e);
    EXPECT_EQ(exportParams(twoTrains("Griffin")).flavor.flavor, Flavor::Griffin);
    EXPECT_EQ(exportParams(twoTrains("MakerBot")).flavor.flavor, Flavor::Unknown);
}

TEST(OutputParams, ExtruderVolumesFromFilamentLengthOrVolume) {
    const ResolvedMachine machine = twoTrains("RepRap (Marlin/Sprinter)");
    PrintSummary summary;
    summary.filament_per_extruder = {1000.0, 0.0};
    describeExtruders(machine, false, summary);
    ASSERT_EQ(summary.extruders.size(), 2U);
    EXPECT_DOUBLE_EQ(summary.extruders[0].volume_used_mm3, 1000.0 * std::numbers::pi * 0.875 * 0.875);
    EXPECT_TRUE(summary.extruders[0].used);
    EXPECT_EQ(summary.extruders[1].volume_used_mm3, 0.0);
    EXPECT_FALSE(summary.extruders[1].used);

    PrintSummary volumetric;
    volumetric.filament_per_extruder = {0.0, 2405.5};
    describeExtruders(machine, true, volumetric);
    EXPECT_EQ(volumetric.extruders[1].volume_used_mm3, 2405.5);
}

}  // namespace
}  // namespace mixengine
