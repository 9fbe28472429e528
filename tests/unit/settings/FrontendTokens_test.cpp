// Start/end G-code token expansion as Cura's frontend does it (settings/FrontendValues.h,
// expandGcodeTokens): {key} from the scope, {key, N} from extruder N, unknown tokens verbatim.
#include <gtest/gtest.h>

#include "settings/FrontendValues.h"

namespace mixengine {
namespace {

ResolvedMachine machine() {
    ResolvedMachine m;
    m.global = Settings("global settings", {{"machine_depth", "235"}, {"initial_extruder_nr", "1"}});
    m.extruders.emplace_back("extruder 0",
                             SettingValues{{"material_print_temperature", "215"}, {"machine_depth", "235"}});
    m.extruders.emplace_back("extruder 1",
                             SettingValues{{"material_print_temperature", "200"}, {"machine_depth", "235"}});
    return m;
}

TEST(SettingsFrontendTokens, SettingTokensExpandedPlaceholdersVerbatim) {
    const ResolvedMachine m = machine();
    EXPECT_EQ(expandGcodeTokens("G28\nG1 Y{machine_depth} ;{print_time}", m.global, m),
              "G28\nG1 Y235 ;{print_time}");
    EXPECT_EQ(
        expandGcodeTokens(";{filament_amount} {filament_weight} {filament_cost} {jobname}", m.global, m),
        ";{filament_amount} {filament_weight} {filament_cost} {jobname}");
    EXPECT_EQ(expandGcodeTokens("{mix_unknown_key} {machine_depth", m.global, m),
              "{mix_unknown_key} {machine_depth");
    EXPECT_EQ(expandGcodeTokens("", m.global, m), "");
}

TEST(SettingsFrontendTokens, ExtruderTokens) {
    const ResolvedMachine m = machine();
    EXPECT_EQ(expandGcodeTokens("M104 S{material_print_temperature, 1}", m.global, m), "M104 S200");
    EXPECT_EQ(expandGcodeTokens("M104 S{material_print_temperature,0}", m.global, m), "M104 S215");
    EXPECT_EQ(expandGcodeTokens("M109 S{material_print_temperature, initial_extruder_nr}", m.global, m),
              "M109 S200");
    EXPECT_EQ(expandGcodeTokens("M104 S{material_print_temperature}", m.extruders[0], m), "M104 S215");
}

}  // namespace
}  // namespace mixengine
