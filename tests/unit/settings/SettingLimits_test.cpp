// Line widths too narrow to print are refused before slicing (settings/SettingLimits.h).
#include <gtest/gtest.h>

#include "../SettingsTestSupport.h"

#include <string>
#include <vector>

#include "common/Error.h"
#include "settings/SettingLimits.h"

namespace mixengine {
namespace {

std::string errorOf(const SettingValues& values, const std::vector<std::string>& given) {
    try {
        checkLineWidths(test::defaultsWith("extruder 0", values), given);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(SettingLimits, OrdinaryWidthsPass) {
    EXPECT_EQ(errorOf({{"line_width", "0.4"},
                       {"wall_line_width_0", "0.35"},
                       {"initial_layer_line_width_factor", "100"}},
                      {}),
              "");
    EXPECT_EQ(errorOf({{"skin_line_width", "0.01"}}, {}), "");  // the limit itself
}

TEST(SettingLimits, NarrowGivenWidthNamesItsKey) {
    const std::string error =
        errorOf({{"line_width", "0.4"}, {"skin_line_width", "0.001"}}, {"skin_line_width"});
    EXPECT_NE(error.find("setting 'skin_line_width'"), std::string::npos) << error;
    EXPECT_EQ(error.find("computed from"), std::string::npos) << error;
}

TEST(SettingLimits, NarrowComputedWidthAlsoNamesTheGivenSettings) {
    const std::string error = errorOf({{"line_width", "0.001"}}, {"machine_nozzle_size"});
    EXPECT_NE(error.find("setting 'line_width'"), std::string::npos) << error;
    EXPECT_NE(error.find("computed from the settings given: machine_nozzle_size"), std::string::npos)
        << error;
}

TEST(SettingLimits, FirstLayerFactorIsChecked) {
    const std::string error = errorOf({{"line_width", "0.4"}, {"initial_layer_line_width_factor", "1"}},
                                      {"initial_layer_line_width_factor"});
    EXPECT_NE(error.find("setting 'initial_layer_line_width_factor'"), std::string::npos) << error;
}

}  // namespace
}  // namespace mixengine
