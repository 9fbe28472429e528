// `mixengine slice` argument parsing (communication/CommandLineParser.h): the focus rules of
// CuraEngine 4.13's command line, the option forms and the errors.
#include "communication/CommandLineParser.h"

#include <gtest/gtest.h>

#include "unit/settings/ScratchDir.h"

namespace mixengine {
namespace {

using unit::contains;
using unit::inputErrorOf;

SliceRequest parse(const std::vector<std::string>& args) {
    return parseSliceArguments(args).request;
}

TEST(CommandLine, Defaults) {
    const ParsedSliceArgs parsed = parseSliceArguments({});
    const SliceRequest& r = parsed.request;
    EXPECT_EQ(r.definition, "fdmprinter");
    EXPECT_TRUE(r.user.global.empty());
    EXPECT_TRUE(r.user.extruders.empty());
    ASSERT_EQ(r.groups.size(), 1U);
    EXPECT_TRUE(r.groups[0].meshes.empty());
    EXPECT_TRUE(r.output.empty());
    EXPECT_EQ(r.threads, 0);
    EXPECT_EQ(r.verbosity, 0);
    EXPECT_FALSE(r.progress);
    EXPECT_TRUE(parsed.dump_layers_dir.empty());
}

TEST(CommandLine, SettingsFollowTheFocus) {
    const SliceRequest r =
        parse({"-s", "layer_height=0.2", "-e1", "-s", "material_diameter=1.75", "-g", "-s", "group_key=g",
               "-l", "a.stl", "-s", "infill_sparse_density=10", "-s", "x=mesh"});
    EXPECT_EQ(r.user.global, (SettingValues{{"layer_height", "0.2"}}));
    ASSERT_EQ(r.user.extruders.count(1), 1U);
    EXPECT_EQ(r.user.extruders.at(1), (SettingValues{{"material_diameter", "1.75"}}));
    ASSERT_EQ(r.groups.size(), 1U);
    EXPECT_EQ(r.groups[0].settings, (SettingValues{{"group_key", "g"}}));
    ASSERT_EQ(r.groups[0].meshes.size(), 1U);
    const MeshInput& mesh = r.groups[0].meshes[0];
    EXPECT_EQ(mesh.name, "a.stl");
    EXPECT_EQ(mesh.file.value_or(""), "a.stl");
    EXPECT_EQ(mesh.settings, (SettingValues{{"infill_sparse_density", "10"}, {"x", "mesh"}}));
}

TEST(CommandLine, ExtruderFocusAloneCreatesTheTrainEntry) {
    const SliceRequest r = parse({"-e2"});
    ASSERT_EQ(r.user.extruders.count(2), 1U);
    EXPECT_TRUE(r.user.extruders.at(2).empty());
    EXPECT_EQ(r.user.extruders.size(), 1U);
}

TEST(CommandLine, NextStartsANewGroupInFocus) {
    const SliceRequest r =
        parse({"-l", "a.stl", "--next", "-s", "k=5", "-l", "b.stl", "-l", "c.stl", "-s", "m=c"});
    ASSERT_EQ(r.groups.size(), 2U);
    ASSERT_EQ(r.groups[0].meshes.size(), 1U);
    EXPECT_EQ(r.groups[0].meshes[0].name, "a.stl");
    EXPECT_TRUE(r.groups[0].settings.empty());
    EXPECT_EQ(r.groups[1].settings, (SettingValues{{"k", "5"}}));
    ASSERT_EQ(r.groups[1].meshes.size(), 2U);
    EXPECT_EQ(r.groups[1].meshes[0].name, "b.stl");
    EXPECT_TRUE(r.groups[1].meshes[0].settings.empty());
    EXPECT_EQ(r.groups[1].meshes[1].settings, (SettingValues{{"m", "c"}}));
    EXPECT_TRUE(r.user.global.empty());
}

TEST(CommandLine, SettingForms) {
    const SliceRequest r = parse({"-s", "machine_start_gcode=G1 X=5", "-sinline=1", "-s",
                                  "quoted=\"My Printer\"", "-s", "empty=", "-s", "later=1", "-s", "later=2"});
    EXPECT_EQ(r.user.global.at("machine_start_gcode"), "G1 X=5");
    EXPECT_EQ(r.user.global.at("inline"), "1");
    EXPECT_EQ(r.user.global.at("quoted"), "My Printer");
    EXPECT_EQ(r.user.global.at("empty"), "");
    EXPECT_EQ(r.user.global.at("later"), "2");
    EXPECT_EQ(splitSettingArgument("a=b=c"), (std::pair<std::string, std::string>{"a", "b=c"}));
}

TEST(CommandLine, OtherOptions) {
    const ParsedSliceArgs parsed = parseSliceArguments(
        {"-v", "-v", "-p", "-m2", "-j", "creality_ender3", "-o", "out/x.gcode", "--dump-layers", "dump"});
    const SliceRequest& r = parsed.request;
    EXPECT_EQ(r.verbosity, 2);
    EXPECT_TRUE(r.progress);
    EXPECT_EQ(r.threads, 2);
    EXPECT_EQ(r.definition, "creality_ender3");
    EXPECT_EQ(r.output, "out/x.gcode");
    EXPECT_EQ(parsed.dump_layers_dir, "dump");
    EXPECT_EQ(parse({"-m", "3"}).threads, 3);
    EXPECT_EQ(parse({"-vv"}).verbosity, 2);
}

TEST(CommandLine, RotationMatrixBeforeLoadAppliesToThatModel) {
    const SliceRequest r = parse({"-s", "mesh_rotation_matrix=[[1,0,0],[0,0,-1],[0,1,0]]", "-l", "a.stl",
                                  "-s", "mesh_rotation_matrix=[[2,0,0],[0,2,0],[0,0,2]]", "-e0", "-s",
                                  "mesh_rotation_matrix=[[3,0,0],[0,3,0],[0,0,3]]", "-l", "b.stl"});
    ASSERT_EQ(r.groups[0].meshes.size(), 2U);
    const Matrix3& a = r.groups[0].meshes[0].transform;
    EXPECT_EQ(a.m[1][2], -1.0);
    EXPECT_EQ(a.m[2][1], 1.0);
    EXPECT_EQ(a.m[1][1], 0.0);
    EXPECT_EQ(a.apply({0, 1, 0}), (Vec3{0, 0, 1}));
    // The value given after -l a.stl belongs to a.stl (too late for it); b.stl takes the -e0 value.
    EXPECT_EQ(r.groups[0].meshes[0].settings.at("mesh_rotation_matrix"), "[[2,0,0],[0,2,0],[0,0,2]]");
    EXPECT_EQ(r.groups[0].meshes[1].transform.m[0][0], 3.0);
}

TEST(CommandLine, NoRotationMatrixIsIdentity) {
    const SliceRequest r = parse({"-l", "a.stl", "-s", "mesh_rotation_matrix=[[2,0,0],[0,2,0],[0,0,2]]"});
    EXPECT_EQ(r.groups[0].meshes[0].transform.apply({1, 2, 3}), (Vec3{1, 2, 3}));
}

TEST(CommandLine, MalformedRotationMatrixIsAnInputError) {
    const std::string message = inputErrorOf([] {
        parse({"-s", "mesh_rotation_matrix=[[1,0],[0,1]]", "-l", "a.stl"});
    });
    EXPECT_TRUE(contains(message, "mesh_rotation_matrix")) << message;
}

TEST(CommandLine, DefaultExtruderIsTheLastEOption) {
    const SliceRequest r = parse({"-l", "zero.stl", "-e1", "-l", "one.stl", "-e2", "-e0", "-l", "back.stl",
                                  "-e1", "-g", "--next", "-l", "next.stl"});
    EXPECT_EQ(r.groups[0].meshes[0].default_extruder, 0);
    EXPECT_EQ(r.groups[0].meshes[1].default_extruder, 1);
    EXPECT_EQ(r.groups[0].meshes[2].default_extruder, 0);
    EXPECT_EQ(r.groups[1].meshes[0].default_extruder, 1);
}

TEST(CommandLine, ErrorsNameTheWord) {
    struct Case {
        std::vector<std::string> args;
        const char* word;
    };
    const Case cases[] = {
        {{"-s", "noequals"}, "noequals"},
        {{"-s", "=value"}, "=value"},
        {{"-s"}, "-s"},
        {{"-e"}, "-e"},
        {{"-ex"}, "'x'"},
        {{"-e1a"}, "'1a'"},
        {{"-l"}, "-l"},
        {{"-o"}, "-o"},
        {{"-j"}, "-j"},
        {{"-m"}, "-m"},
        {{"-mx"}, "-m"},
        {{"--bogus"}, "--bogus"},
        {{"model.stl"}, "model.stl"},
        {{"-x"}, "-x"},
    };
    for (const Case& c : cases) {
        const std::string message = inputErrorOf([&] { parse(c.args); });
        EXPECT_TRUE(contains(message, c.word)) << c.args[0] << ": " << message;
    }
}

}  // namespace
}  // namespace mixengine
