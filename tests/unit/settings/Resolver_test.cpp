// Settings resolution (settings/Resolver.h): the order of the sources, mesh views, and
// limit_to_extruder, on a small hand-made definition set and on Cura's real files.
#include "settings/Resolver.h"

#include <gtest/gtest.h>

#include <optional>
#include <string>

#include "unit/settings/ScratchDir.h"

namespace mixengine {
namespace {

using unit::contains;
using unit::inputErrorOf;

void define(SettingDefinitionMap& map, const std::string& key, const std::string& type,
            const std::string& value, bool per_extruder, std::optional<std::string> limit = std::nullopt) {
    SettingDefinition& def = map[key];
    def.key = key;
    def.type = type;
    def.default_value = value;
    def.settable_per_extruder = per_extruder;
    def.settable_per_mesh = true;
    def.limit_to_extruder = std::move(limit);
}

/// A two-extruder machine shaped like fdmprinter + two extruder files: material_diameter 2.85 in the
/// machine, 1.75 in both extruder files.
DefinitionSet twoExtruderMachine() {
    DefinitionSet set;
    set.machine_id = "test_dual";
    define(set.settings, "material_diameter", "float", "2.85", true);
    define(set.settings, "layer_height", "float", "0.1", false);
    define(set.settings, "infill_extruder_nr", "optional_extruder", "-1", false);
    define(set.settings, "infill_line_distance", "float", "6.0", true, "infill_extruder_nr");
    define(set.settings, "wall_line_count", "int", "2", true, "1");  // always read from extruder 1
    define(set.settings, "support_roof_enable", "bool", "False", true);
    define(set.settings, "support_roof_extruder_nr", "extruder", "1", false);
    define(set.settings, "support_angle", "float", "50.0", true,
           "support_roof_extruder_nr if support_roof_enable else 0");
    for (int position : {0, 1}) {
        ExtruderDefinition extruder;
        extruder.id = "test_dual_extruder_" + std::to_string(position);
        extruder.position = position;
        define(extruder.overrides, "material_diameter", "float", "1.75", true);
        define(extruder.overrides, "extruder_nr", "extruder", std::to_string(position), true);
        set.extruders.push_back(std::move(extruder));
    }
    return set;
}

TEST(Resolver, DefinitionsAloneExtruderFileBeatsMachine) {
    const ResolvedMachine machine = resolveMachine(twoExtruderMachine(), {});
    EXPECT_EQ(machine.global.scope(), "global settings");
    EXPECT_EQ(machine.global.text(key::material_diameter), "2.85");
    ASSERT_EQ(machine.extruders.size(), 2U);
    EXPECT_EQ(machine.extruders[1].scope(), "extruder 1");
    EXPECT_EQ(machine.extruders[0].text(key::material_diameter), "1.75");
    EXPECT_EQ(machine.extruders[1].text(key::material_diameter), "1.75");
    EXPECT_EQ(machine.extruders[0].text(key::extruder_nr), "0");
    EXPECT_EQ(machine.extruders[1].text(key::extruder_nr), "1");
    EXPECT_EQ(machine.extruders[1].text(key::layer_height), "0.1");
}

TEST(Resolver, OrderExtruderUserThenGlobalUserThenDefinitions) {
    UserSettings user;
    user.global["material_diameter"] = "2.0";
    user.extruders[1]["material_diameter"] = "3.0";
    const ResolvedMachine machine = resolveMachine(twoExtruderMachine(), user);
    EXPECT_EQ(machine.global.text(key::material_diameter), "2.0");
    EXPECT_EQ(machine.extruders[0].text(key::material_diameter), "2.0");  // -s beats the extruder file
    EXPECT_EQ(machine.extruders[1].text(key::material_diameter), "3.0");  // -e1 -s beats -s
}

TEST(Resolver, UnknownUserKeysAreKept) {
    const DefinitionSet defs = twoExtruderMachine();
    UserSettings user;
    user.global["mix_plugin_key"] = "abc";
    user.extruders[0]["mix_extruder_key"] = "x";
    const ResolvedMachine machine = resolveMachine(defs, user);
    EXPECT_EQ(machine.global.all().at("mix_plugin_key"), "abc");
    EXPECT_EQ(machine.extruders[1].all().at("mix_plugin_key"), "abc");
    EXPECT_EQ(machine.extruders[0].all().at("mix_extruder_key"), "x");
    EXPECT_EQ(machine.extruders[1].find("mix_extruder_key"), nullptr);
    const Settings group = resolveMeshGroup(machine, {}, 0);
    const Settings mesh = resolveMesh(defs, user, machine, group, {{"mix_mesh_key", "m"}}, 0, "cube.stl");
    EXPECT_EQ(mesh.all().at("mix_plugin_key"), "abc");
    EXPECT_EQ(mesh.all().at("mix_extruder_key"), "x");
    EXPECT_EQ(mesh.all().at("mix_mesh_key"), "m");
}

TEST(Resolver, TrainCountFollowsMachineExtruderCountAndUserTrains) {
    DefinitionSet single = twoExtruderMachine();
    single.extruders.resize(1);
    EXPECT_EQ(resolveMachine(single, {}).extruders.size(), 1U);
    UserSettings e2;
    e2.extruders[2]["material_diameter"] = "1.0";
    const ResolvedMachine machine = resolveMachine(single, e2);
    ASSERT_EQ(machine.extruders.size(), 3U);
    EXPECT_EQ(machine.extruders[1].text(key::material_diameter), "2.85");  // no extruder file: the machine's
    EXPECT_EQ(machine.extruders[2].text(key::material_diameter), "1.0");
}

// BUG (engine/settings/Resolver.cpp resolveMachine / StackEvaluator, working-tree version): a train
// without an extruder definition file (-e1 on fdmprinter, or machine_extruder_count above the
// number of machine_extruder_trains) has no extruder_nr at all — Settings::text throws "setting
// 'extruder_nr' has no value in extruder 1". CuraEngine gives every ExtruderTrain its extruder_nr,
// and the previous Resolver set values["extruder_nr"] = nr for every train.
TEST(Resolver, EveryTrainKnowsItsNumber) {
    const DefinitionSet defs = loadDefinitionSet(
        "fdmprinter", {"/usr/share/cura/resources/definitions", "/usr/share/cura/resources/extruders"});
    UserSettings user;
    user.extruders[1]["material_diameter"] = "1.75";
    const ResolvedMachine machine = resolveMachine(defs, user);
    ASSERT_EQ(machine.extruders.size(), 2U);
    EXPECT_EQ(machine.extruders[0].text(key::extruder_nr), "0");
    EXPECT_EQ(machine.extruders[1].text(key::extruder_nr), "1");
}

TEST(Resolver, MeshViewFromItsExtruderGroupAndOwnValues) {
    const DefinitionSet defs = twoExtruderMachine();
    UserSettings user;
    user.extruders[1]["material_diameter"] = "3.0";
    const ResolvedMachine machine = resolveMachine(defs, user);
    const Settings group = resolveMeshGroup(machine, {{"layer_height", "0.2"}}, 1);
    EXPECT_EQ(group.scope(), "mesh group 1");
    EXPECT_EQ(group.text(key::layer_height), "0.2");

    const Settings on_default = resolveMesh(defs, user, machine, group, {}, 1, "cube.stl");
    EXPECT_EQ(on_default.scope(), "mesh 'cube.stl'");
    EXPECT_EQ(on_default.text(key::extruder_nr), "1");
    EXPECT_EQ(on_default.text(key::material_diameter), "3.0");
    EXPECT_EQ(on_default.text(key::layer_height), "0.2");  // the group's value

    const Settings by_setting =
        resolveMesh(defs, user, machine, group, {{"extruder_nr", "0"}}, 1, "cube.stl");
    EXPECT_EQ(by_setting.text(key::extruder_nr), "0");
    EXPECT_EQ(by_setting.text(key::material_diameter), "1.75");

    const Settings own = resolveMesh(defs, user, machine, group, {{"layer_height", "0.3"}}, 0, "cube.stl");
    EXPECT_EQ(own.text(key::layer_height), "0.3");
}

TEST(Resolver, LimitToExtruderReadsTheTargetTrain) {
    const DefinitionSet defs = twoExtruderMachine();
    UserSettings user;
    user.global["infill_extruder_nr"] = "1";
    user.extruders[0]["infill_line_distance"] = "9.0";
    user.extruders[1]["infill_line_distance"] = "2.5";
    user.extruders[1]["wall_line_count"] = "5";
    const ResolvedMachine machine = resolveMachine(defs, user);
    const Settings group = resolveMeshGroup(machine, {}, 0);
    EXPECT_EQ(resolveMesh(defs, user, machine, group, {}, 0, "a").text(key::infill_line_distance), "2.5");
    EXPECT_EQ(resolveMesh(defs, user, machine, group, {}, 1, "b").text(key::infill_line_distance), "2.5");
    // A value set on the mesh itself is not overridden by the limit.
    const Settings own = resolveMesh(defs, user, machine, group, {{"infill_line_distance", "4.0"}}, 0, "c");
    EXPECT_EQ(own.text(key::infill_line_distance), "4.0");
    // A constant limit_to_extruder always names that train.
    EXPECT_EQ(resolveMesh(defs, user, machine, group, {}, 0, "d").text(key::wall_line_count), "5");
}

TEST(Resolver, LimitsPointingAtEachOtherDoNotRecurse) {
    DefinitionSet defs = twoExtruderMachine();
    define(defs.settings, "mix_index", "extruder", "0", true);
    define(defs.settings, "mix_limited", "str", "none", true, "mix_index");
    UserSettings user;
    user.extruders[0] = {{"mix_index", "1"}, {"mix_limited", "A"}};
    user.extruders[1] = {{"mix_index", "0"}, {"mix_limited", "B"}};
    const ResolvedMachine machine = resolveMachine(defs, user);
    const Settings group = resolveMeshGroup(machine, {}, 0);
    // Each mesh reads the other train's own value, once.
    EXPECT_EQ(resolveMesh(defs, user, machine, group, {}, 0, "a").all().at("mix_limited"), "B");
    EXPECT_EQ(resolveMesh(defs, user, machine, group, {}, 1, "b").all().at("mix_limited"), "A");
}

TEST(Resolver, LimitToExtruderExpression) {
    const DefinitionSet defs = twoExtruderMachine();
    UserSettings user;
    user.extruders[0]["support_angle"] = "40.0";
    user.extruders[1]["support_angle"] = "60.0";
    for (const char* roof : {"False", "True"}) {
        user.global["support_roof_enable"] = roof;
        const ResolvedMachine machine = resolveMachine(defs, user);
        const Settings mesh = resolveMesh(defs, user, machine, resolveMeshGroup(machine, {}, 0), {}, 0, "a");
        // support_roof_extruder_nr (1) if support_roof_enable else 0
        EXPECT_EQ(mesh.text(key::support_angle), std::string(roof) == "True" ? "60.0" : "40.0") << roof;
    }
}

TEST(Resolver, LimitToExtruderWithoutTargetKeepsOwnValue) {
    const DefinitionSet defs = twoExtruderMachine();
    for (const char* target : {"-1", "2", "99"}) {
        UserSettings user;
        user.global["infill_extruder_nr"] = target;
        user.extruders[0]["infill_line_distance"] = "9.0";
        const ResolvedMachine machine = resolveMachine(defs, user);
        const Settings mesh = resolveMesh(defs, user, machine, resolveMeshGroup(machine, {}, 0), {}, 0, "a");
        EXPECT_EQ(mesh.text(key::infill_line_distance), "9.0") << target;
    }
}

TEST(Resolver, MeshExtruderOutOfRange) {
    const DefinitionSet defs = twoExtruderMachine();
    const UserSettings user;
    const ResolvedMachine machine = resolveMachine(defs, user);
    const Settings group = resolveMeshGroup(machine, {}, 0);
    std::string message = inputErrorOf([&] { resolveMesh(defs, user, machine, group, {}, 2, "cube.stl"); });
    EXPECT_TRUE(contains(message, "cube.stl") && contains(message, "2")) << message;
    message = inputErrorOf([&] {
        resolveMesh(defs, user, machine, group, {{"extruder_nr", "-1"}}, 0, "cube.stl");
    });
    EXPECT_TRUE(contains(message, "cube.stl") && contains(message, "-1")) << message;
    message = inputErrorOf([&] {
        resolveMesh(defs, user, machine, group, {{"extruder_nr", "one"}}, 0, "cube.stl");
    });
    EXPECT_TRUE(contains(message, "extruder_nr") && contains(message, "one")) << message;
}

TEST(Resolver, MalformedLimitTargetNamesTheIndexSetting) {
    const DefinitionSet defs = twoExtruderMachine();
    UserSettings user;
    user.global["infill_extruder_nr"] = "abc";
    const std::string message = inputErrorOf([&] {
        const ResolvedMachine machine = resolveMachine(defs, user);
        resolveMesh(defs, user, machine, resolveMeshGroup(machine, {}, 0), {}, 0, "a");
    });
    EXPECT_TRUE(contains(message, "infill_extruder_nr") && contains(message, "abc")) << message;
}

TEST(Resolver, RealDualMachineLimitToExtruder) {
    const DefinitionSet defs =
        loadDefinitionSet("ultimaker_original_dual",
                          {"/usr/share/cura/resources/definitions", "/usr/share/cura/resources/extruders"});
    ASSERT_EQ(defs.find("infill_line_distance")->limit_to_extruder.value_or(""), "infill_extruder_nr");
    UserSettings user;
    user.global["infill_extruder_nr"] = "1";
    user.extruders[1]["infill_line_distance"] = "4.0";
    const ResolvedMachine machine = resolveMachine(defs, user);
    ASSERT_EQ(machine.extruders.size(), 2U);
    EXPECT_EQ(machine.extruders[0].text(key::machine_nozzle_offset_y), "0.0");
    EXPECT_EQ(machine.extruders[1].text(key::machine_nozzle_offset_y), "21.6");
    const Settings group = resolveMeshGroup(machine, {}, 0);
    const Settings mesh = resolveMesh(defs, user, machine, group, {{"extruder_nr", "0"}}, 0, "left.stl");
    EXPECT_EQ(mesh.text(key::infill_line_distance), "4.0");
    EXPECT_EQ(mesh.text(key::machine_nozzle_offset_y), "0.0");
}

}  // namespace
}  // namespace mixengine
