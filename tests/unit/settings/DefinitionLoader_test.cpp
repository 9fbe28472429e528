// Loading Cura definition files (settings/DefinitionSet.h) from Cura's installed resources and from
// a CURA_ENGINE_SEARCH_PATH-style list holding custom files.
#include <gtest/gtest.h>

#include <algorithm>

#include "settings/DefinitionSet.h"
#include "unit/settings/ScratchDir.h"

namespace mixengine {
namespace {

namespace fs = std::filesystem;
using unit::contains;
using unit::inputErrorOf;
using unit::ScratchDir;

const fs::path kCura = "/usr/share/cura/resources";

std::vector<fs::path> curaSearch() {
    return {kCura / "definitions", kCura / "extruders"};
}

std::vector<std::string> fileNames(const DefinitionSet& set) {
    std::vector<std::string> names;
    for (const fs::path& file : set.files)
        names.push_back(file.filename().string());
    return names;
}

TEST(DefinitionLoader, FdmprinterAloneHasOneFdmextruderTrain) {
    const DefinitionSet set = loadDefinitionSet("fdmprinter", curaSearch());
    EXPECT_EQ(set.machine_id, "fdmprinter");
    EXPECT_EQ(set.settings.size(), 575U);  // every non-category node of fdmprinter.def.json (Cura 4.13)
    ASSERT_EQ(set.extruders.size(), 1U);
    EXPECT_EQ(set.extruders[0].id, "fdmextruder");
    EXPECT_EQ(set.extruders[0].position, 0);
    EXPECT_EQ(fileNames(set), (std::vector<std::string>{"fdmprinter.def.json", "fdmextruder.def.json"}));
    EXPECT_EQ(set.find("resolution"), nullptr);        // a category, not a setting
    EXPECT_EQ(set.find("machine_settings"), nullptr);  // likewise
    EXPECT_EQ(set.metadata.at("visible"), "False");
    EXPECT_EQ(set.metadata.at("setting_version"), "19");
}

TEST(DefinitionLoader, SettingPropertiesAreKeptAsPythonText) {
    const DefinitionSet set = loadDefinitionSet("fdmprinter", curaSearch());
    const SettingDefinition* layer_height = set.find("layer_height");
    ASSERT_NE(layer_height, nullptr);
    EXPECT_EQ(layer_height->key, "layer_height");
    EXPECT_EQ(layer_height->type, "float");
    EXPECT_EQ(layer_height->default_value, "0.1");
    EXPECT_EQ(layer_height->unit, "mm");
    EXPECT_TRUE(layer_height->settable_per_mesh == false);
    const SettingDefinition* width = set.find("machine_width");
    ASSERT_NE(width, nullptr);
    EXPECT_EQ(width->default_value, "100");
    const SettingDefinition* limited = set.find("infill_line_distance");
    ASSERT_NE(limited, nullptr);
    ASSERT_TRUE(limited->limit_to_extruder.has_value());
    EXPECT_EQ(*limited->limit_to_extruder, "infill_extruder_nr");
    ASSERT_TRUE(limited->value_formula.has_value());
    const SettingDefinition* flavor = set.find("machine_gcode_flavor");
    ASSERT_NE(flavor, nullptr);
    EXPECT_EQ(flavor->type, "enum");
    EXPECT_EQ(flavor->default_value, "RepRap (Marlin/Sprinter)");
    EXPECT_NE(std::find(flavor->enum_options.begin(), flavor->enum_options.end(), "RepRap (Volumetric)"),
              flavor->enum_options.end());
    const SettingDefinition* head = set.find("machine_head_with_fans_polygon");
    ASSERT_NE(head, nullptr);
    EXPECT_EQ(head->default_value, "[[-20, 10], [10, 10], [10, -10], [-20, -10]]");
}

TEST(DefinitionLoader, ExplicitSettableFlagsAreKept) {
    const DefinitionSet set = loadDefinitionSet("fdmprinter", curaSearch());
    EXPECT_FALSE(set.find("layer_height")->settable_per_mesh);
    EXPECT_FALSE(set.find("layer_height")->settable_per_extruder);
    EXPECT_FALSE(set.find("retraction_amount")->settable_per_mesh);
    EXPECT_TRUE(set.find("retraction_amount")->settable_per_extruder);
    EXPECT_TRUE(set.find("speed_print")->settable_per_mesh);
}

// BUG (engine/settings/SettingDefinition.h: `bool settable_per_mesh = false; bool
// settable_per_extruder = false;`, kept by DefinitionLoader.cpp applyProperties when the property is
// absent): Cura registers both properties with default=True (CuraApplication.py:
// addSupportedProperty("settable_per_extruder", ..., default=True)). 232 fdmprinter settings omit
// settable_per_extruder (speed_print, wall_thickness, infill_line_distance, ...) and 15 omit both
// (material_guid, conical_overhang_enabled, ...); they load as not settable, so per-extruder values
// and limit_to_extruder for them are dropped by code that honours the flag (StackEvaluator).
TEST(DefinitionLoader, SettableFlagsDefaultToTrueLikeCura) {
    const DefinitionSet set = loadDefinitionSet("fdmprinter", curaSearch());
    EXPECT_TRUE(set.find("speed_print")->settable_per_extruder);
    EXPECT_TRUE(set.find("infill_line_distance")->settable_per_extruder);
    EXPECT_TRUE(set.find("conical_overhang_enabled")->settable_per_mesh);
    EXPECT_TRUE(set.find("conical_overhang_enabled")->settable_per_extruder);
}

void expectEnder3(const DefinitionSet& set) {
    EXPECT_EQ(set.machine_id, "creality_ender3");
    EXPECT_EQ(fileNames(set), (std::vector<std::string>{
                                  "creality_ender3.def.json", "creality_base.def.json", "fdmprinter.def.json",
                                  "creality_base_extruder_0.def.json", "fdmextruder.def.json"}));
    ASSERT_NE(set.find("machine_width"), nullptr);
    EXPECT_EQ(set.find("machine_width")->default_value,
              "235");  // creality_ender3 overrides (fdmprinter: 100)
    EXPECT_EQ(set.find("machine_depth")->default_value, "235");
    EXPECT_EQ(set.find("machine_height")->default_value, "250");
    ASSERT_EQ(set.extruders.size(), 1U);
    EXPECT_EQ(set.extruders[0].id, "creality_base_extruder_0");
    EXPECT_EQ(set.extruders[0].position, 0);
    ASSERT_EQ(set.extruders[0].overrides.count("material_diameter"), 1U);
    EXPECT_EQ(set.extruders[0].overrides.at("material_diameter").default_value, "1.75");
    EXPECT_EQ(set.metadata.at("platform"), "creality_ender3.3mf");  // most derived metadata wins
    EXPECT_EQ(set.metadata.at("visible"), "True");
}

TEST(DefinitionLoader, Ender3ById) {
    expectEnder3(loadDefinitionSet("creality_ender3", curaSearch()));
}

TEST(DefinitionLoader, Ender3ByPath) {
    expectEnder3(
        loadDefinitionSet((kCura / "definitions" / "creality_ender3.def.json").string(), curaSearch()));
}

TEST(DefinitionLoader, DualMachineHasTwoTrainsInPositionOrder) {
    const DefinitionSet set = loadDefinitionSet("ultimaker_original_dual", curaSearch());
    EXPECT_EQ(set.find("machine_extruder_count")->default_value, "2");
    ASSERT_EQ(set.extruders.size(), 2U);
    EXPECT_EQ(set.extruders[0].id, "ultimaker_original_dual_1st");
    EXPECT_EQ(set.extruders[0].position, 0);
    EXPECT_EQ(set.extruders[1].id, "ultimaker_original_dual_2nd");
    EXPECT_EQ(set.extruders[1].position, 1);
    EXPECT_EQ(set.extruders[0].overrides.at("machine_nozzle_offset_y").default_value, "0.0");
    EXPECT_EQ(set.extruders[1].overrides.at("machine_nozzle_offset_y").default_value, "21.6");
    EXPECT_EQ(set.extruders[1].overrides.at("extruder_nr").default_value, "1");
}

TEST(DefinitionLoader, SearchPathFromEnvironmentText) {
    const std::vector<fs::path> dirs = defaultSearchPath("/a:/b;/c::/d");
    ASSERT_GE(dirs.size(), 6U);
    EXPECT_EQ(dirs[0], "/a");
    EXPECT_EQ(dirs[1], "/b");
    EXPECT_EQ(dirs[2], "/c");
    EXPECT_EQ(dirs[3], "/d");
    EXPECT_EQ(dirs[dirs.size() - 2], kCura / "definitions");
    EXPECT_EQ(dirs.back(), kCura / "extruders");
    const std::vector<fs::path> none = defaultSearchPath(nullptr);
    EXPECT_EQ(none.size(), dirs.size() - 4);
}

constexpr const char* kCustomMachine = R"({
  "version": 2, "name": "Custom", "inherits": "fdmprinter",
  "metadata": {"machine_extruder_trains": {"1": "mix_custom_extruder_1", "0": "mix_custom_extruder_0"}},
  "overrides": {
    "machine_width": {"default_value": 321.5},
    "machine_extruder_count": {"default_value": 2},
    "machine_depth": {"value": "machine_width"},
    "mix_custom_new_key": {"type": "int", "default_value": 7}
  }
})";

std::string customExtruder(int position, const char* diameter) {
    return R"({"version": 2, "name": "E", "inherits": "fdmextruder", "metadata": {"position": ")" +
           std::to_string(position) + R"("}, "overrides": {"extruder_nr": {"default_value": )" +
           std::to_string(position) + R"(}, "material_diameter": {"default_value": )" + diameter + "}}}";
}

TEST(DefinitionLoader, CustomDefinitionOnTheSearchPath) {
    ScratchDir dir;
    dir.write("mix_custom.def.json", kCustomMachine);
    dir.write("mix_custom_extruder_0.def.json", customExtruder(0, "1.75"));
    dir.write("mix_custom_extruder_1.def.json", customExtruder(1, "2.85"));
    const DefinitionSet set = loadDefinitionSet("mix_custom", defaultSearchPath(dir.path().c_str()));
    EXPECT_EQ(set.machine_id, "mix_custom");
    EXPECT_EQ(set.files.front(), dir.path() / "mix_custom.def.json");
    EXPECT_EQ(set.find("machine_width")->default_value, "321.5");
    // An override with only a `value` formula keeps the inherited default.
    EXPECT_EQ(set.find("machine_depth")->default_value, "100");
    EXPECT_EQ(set.find("machine_depth")->value_formula.value_or(""), "machine_width");
    EXPECT_EQ(set.find("machine_depth")->type, "float");
    ASSERT_NE(set.find("mix_custom_new_key"), nullptr);
    EXPECT_EQ(set.find("mix_custom_new_key")->default_value, "7");
    // fdmprinter's settings, the custom key and MixEngine's own (settings/mixengine/*.def.json): 596 before
    // mixing_raft_ratio, mixing_support_ratio (issue 15), the colour keys of issue 18 (target, gradient,
    // paint), the chamber's stages, transition tolerance and purge tower (issue 26) and the gradient axis
    // (issue 27), the painted edges' blend and the core's ratio (issue 27).
    EXPECT_EQ(set.settings.size(), 608U);
    EXPECT_NE(set.find("mixing_mode"), nullptr);
    EXPECT_NE(set.find("dual_orientation_optimize"), nullptr);
    ASSERT_EQ(set.extruders.size(), 2U);
    EXPECT_EQ(set.extruders[0].id, "mix_custom_extruder_0");
    EXPECT_EQ(set.extruders[1].id, "mix_custom_extruder_1");
    EXPECT_EQ(set.extruders[0].overrides.at("material_diameter").default_value, "1.75");
    EXPECT_EQ(set.extruders[1].overrides.at("material_diameter").default_value, "2.85");
}

TEST(DefinitionLoader, MissingDefinitionIsNamed) {
    std::string message = inputErrorOf([] { loadDefinitionSet("mix_no_such_printer", curaSearch()); });
    EXPECT_TRUE(contains(message, "mix_no_such_printer")) << message;

    ScratchDir dir;
    dir.write("orphan.def.json", R"({"version": 2, "inherits": "mix_missing_parent"})");
    message = inputErrorOf([&] { loadDefinitionSet("orphan", {dir.path()}); });
    EXPECT_TRUE(contains(message, "mix_missing_parent")) << message;

    dir.write(
        "no_train.def.json",
        R"({"version": 2, "inherits": "fdmprinter", "metadata": {"machine_extruder_trains": {"0": "mix_gone"}}})");
    std::vector<fs::path> search = curaSearch();
    search.insert(search.begin(), dir.path());
    message = inputErrorOf([&] { loadDefinitionSet("no_train", search); });
    EXPECT_TRUE(contains(message, "mix_gone")) << message;
}

TEST(DefinitionLoader, InvalidJsonNamesTheFile) {
    ScratchDir dir;
    const fs::path broken = dir.write("broken.def.json", R"({"version": 2, "inherits": )");
    std::string message = inputErrorOf([&] { loadDefinitionSet(broken.string(), curaSearch()); });
    EXPECT_TRUE(contains(message, broken.string())) << message;

    // A broken parent is named too, not the child that inherits from it.
    dir.write("child.def.json", R"({"version": 2, "inherits": "broken"})");
    message = inputErrorOf([&] { loadDefinitionSet("child", {dir.path()}); });
    EXPECT_TRUE(contains(message, "broken.def.json")) << message;

    const fs::path array = dir.write("array.def.json", "[1, 2]");
    message = inputErrorOf([&] { loadDefinitionSet(array.string(), curaSearch()); });
    EXPECT_TRUE(contains(message, "array.def.json")) << message;
}

TEST(DefinitionLoader, InheritsLoopIsAnError) {
    ScratchDir dir;
    dir.write("loop_a.def.json", R"({"version": 2, "inherits": "loop_b"})");
    dir.write("loop_b.def.json", R"({"version": 2, "inherits": "loop_a"})");
    dir.write("loop_self.def.json", R"({"version": 2, "inherits": "loop_self"})");
    std::string message = inputErrorOf([&] { loadDefinitionSet("loop_a", {dir.path()}); });
    EXPECT_TRUE(contains(message, "loop_a")) << message;
    message = inputErrorOf([&] { loadDefinitionSet("loop_self", {dir.path()}); });
    EXPECT_TRUE(contains(message, "loop_self")) << message;
}

// BUG (engine/settings/DefinitionLoader.cpp, loadChain: `doc.value("inherits", "")`, and
// applyProperties: `it->get<std::string>()` for "type"): a definition whose "inherits" or a
// setting's "type" is not a string lets nlohmann::json::type_error escape instead of the InputError
// naming the file that DefinitionSet.h promises.
TEST(DefinitionLoader, WrongJsonTypesAreInputErrorsNamingTheFile) {
    ScratchDir dir;
    const fs::path numeric = dir.write("numeric.def.json", R"({"version": 2, "inherits": 5})");
    std::string message = inputErrorOf([&] { loadDefinitionSet(numeric.string(), {dir.path()}); });
    EXPECT_TRUE(contains(message, "numeric.def.json")) << message;
    const fs::path typed =
        dir.write("typed.def.json",
                  R"({"version": 2, "inherits": "fdmprinter", "overrides": {"layer_height": {"type": 3}}})");
    std::vector<fs::path> search = curaSearch();
    message = inputErrorOf([&] { loadDefinitionSet(typed.string(), search); });
    EXPECT_TRUE(contains(message, "typed.def.json")) << message;
}

}  // namespace
}  // namespace mixengine
