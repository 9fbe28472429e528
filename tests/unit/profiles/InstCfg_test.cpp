// Reading Cura's *.inst.cfg files (settings/profiles/InstCfg.h) the way Uranium's FastConfigParser
// does, on hand-written text and on real files from /usr/share/cura/resources.
#include "settings/profiles/InstCfg.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "unit/settings/ScratchDir.h"

namespace mixengine {
namespace {

using unit::contains;
using unit::inputErrorOf;

const std::string* valueOf(const InstCfgFile& file, const std::string& key) {
    for (const auto& [k, v] : file.values) {
        if (k == key)
            return &v;
    }
    return nullptr;
}

TEST(ProfileInstCfg, GeneralMetadataAndValues) {
    const InstCfgFile file = parseInstCfg(
        "[general]\nversion = 4\nname = Standard Quality\ndefinition = creality_base\n\n"
        "[metadata]\nsetting_version = 19\ntype = quality\nquality_type = standard\nglobal_quality = True\n\n"
        "[values]\nlayer_height = 0.2\ntop_bottom_thickness = =layer_height_0+layer_height*3\n",
        "base_global_standard", "test");
    EXPECT_EQ(file.id, "base_global_standard");
    EXPECT_EQ(file.name(), "Standard Quality");
    EXPECT_EQ(file.definition(), "creality_base");
    ASSERT_NE(file.meta("quality_type"), nullptr);
    EXPECT_EQ(*file.meta("quality_type"), "standard");
    EXPECT_EQ(*file.meta("global_quality"), "True");
    ASSERT_EQ(file.values.size(), 2u);
    EXPECT_EQ(*valueOf(file, "layer_height"), "0.2");
    EXPECT_EQ(*valueOf(file, "top_bottom_thickness"), "=layer_height_0+layer_height*3");
}

TEST(ProfileInstCfg, FormulaVersusLiteral) {
    ContainerValue formula = containerValueFromText("=layer_height * 2");
    EXPECT_TRUE(formula.is_formula);
    EXPECT_EQ(formula.text, "layer_height * 2");
    ContainerValue literal = containerValueFromText("0.2");
    EXPECT_FALSE(literal.is_formula);
    EXPECT_EQ(literal.text, "0.2");
    ContainerValue text = containerValueFromText("G28 ; home = origin");
    EXPECT_FALSE(text.is_formula);
}

TEST(ProfileInstCfg, ContinuationLinesJoinTheValue) {
    const InstCfgFile file = parseInstCfg(
        "[general]\ndefinition = fdmprinter\n[values]\n"
        "machine_start_gcode = G28\n\tG1 Z5\n\n\tM104 S200\n"
        "speed_print = 50\n"
        "indented = first\n    second line\n",
        "x", "test");
    // a tab after a line break is dropped; other indentation and blank lines stay
    EXPECT_EQ(*valueOf(file, "machine_start_gcode"), "G28\nG1 Z5\n\nM104 S200");
    EXPECT_EQ(*valueOf(file, "speed_print"), "50");
    EXPECT_EQ(*valueOf(file, "indented"), "first\n    second line");
}

TEST(ProfileInstCfg, CommentsAsUraniumReadsThem) {
    // As in FastConfigParser: a comment line without '=' continues the previous value, and
    // "#key = v" is an entry named "#key" (dropped later as an unknown setting).
    const InstCfgFile file = parseInstCfg(
        "[general]\ndefinition = fdmprinter\n[values]\n"
        "machine_nozzle_heat_up_speed = 1.6\n# prime_tower_enable: see CURA-4248\n"
        "#retraction_extra_prime_amount = 0.5\nspeed_print = 80\n",
        "x", "test");
    EXPECT_EQ(*valueOf(file, "machine_nozzle_heat_up_speed"), "1.6\n# prime_tower_enable: see CURA-4248");
    ASSERT_NE(valueOf(file, "#retraction_extra_prime_amount"), nullptr);
    EXPECT_EQ(*valueOf(file, "speed_print"), "80");
}

TEST(ProfileInstCfg, CrLfAndEmptyValues) {
    const InstCfgFile file = parseInstCfg(
        " [general]\r\nname = Fine\r\ndefinition = predator\r\n\r\n[values]\r\na = 1\r\nb =\r\nc = 3\r\n",
        "x", "test");
    EXPECT_EQ(file.definition(), "predator");
    EXPECT_EQ(*valueOf(file, "a"), "1");
    EXPECT_EQ(*valueOf(file, "b"), "");
    EXPECT_EQ(*valueOf(file, "c"), "3");
}

TEST(ProfileInstCfg, MissingDefinitionIsAnError) {
    const std::string message =
        inputErrorOf([] { parseInstCfg("[general]\nname = x\n", "x", "broken.inst.cfg"); });
    EXPECT_TRUE(contains(message, "broken.inst.cfg")) << message;
    EXPECT_TRUE(contains(message, "definition")) << message;
}

TEST(ProfileInstCfg, FileNameGivesTheId) {
    unit::ScratchDir dir;
    const auto path = dir.write("my+profile%21.inst.cfg", "[general]\ndefinition = fdmprinter\n");
    EXPECT_EQ(readInstCfgFile(path).id, "my profile!");
    EXPECT_TRUE(contains(inputErrorOf([&] { readInstCfgFile(dir.path() / "missing.inst.cfg"); }),
                         "missing.inst.cfg"));
}

TEST(ProfileInstCfg, RealQualityFile) {
    const std::filesystem::path path =
        "/usr/share/cura/resources/quality/ultimaker_s5/um_s5_aa0.4_PLA_Normal_Quality.inst.cfg";
    if (!std::filesystem::exists(path))
        GTEST_SKIP() << "Cura resources not installed";
    const InstCfgFile file = readInstCfgFile(path);
    EXPECT_EQ(file.id, "um_s5_aa0.4_PLA_Normal_Quality");
    EXPECT_EQ(*file.meta("variant"), "AA 0.4");
    EXPECT_EQ(*file.meta("material"), "generic_pla");
    EXPECT_EQ(*valueOf(file, "cool_fan_full_at_height"), "=layer_height_0 + 2 * layer_height");
    // the entries after the blank line in [values] are read too
    EXPECT_EQ(*valueOf(file, "raft_airgap"), "0.25");
}

}  // namespace
}  // namespace mixengine
