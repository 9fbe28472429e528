// Typed parsing of setting text (settings/ValueParse.h) and the Settings view built on it
// (settings/Settings.h). Modelled on CuraEngine's settings-parsing cases: bool, real, integer,
// coord (mm → µm), ratio, angle, polygon(s), matrix, vector, missing key, overlay.
#include "settings/ValueParse.h"

#include <gtest/gtest.h>

#include <array>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include "settings/Settings.h"
#include "unit/settings/ScratchDir.h"

namespace mixengine {
namespace {

using unit::contains;
using unit::inputErrorOf;

TEST(ValueParse, BooleansInEveryFormCuraSends) {
    for (const char* text : {"True", "true", "TRUE", "yes", "on", "1", " True "}) {
        EXPECT_TRUE(parseBool("support_enable", text)) << text;
    }
    for (const char* text : {"False", "false", "no", "off", "0"}) {
        EXPECT_FALSE(parseBool("support_enable", text)) << text;
    }
}

TEST(ValueParse, BooleanRejectsWordsNamingKeyAndValue) {
    const std::string message = inputErrorOf([] { parseBool("support_enable", "maybe"); });
    EXPECT_TRUE(contains(message, "support_enable")) << message;
    EXPECT_TRUE(contains(message, "maybe")) << message;
}

TEST(ValueParse, Reals) {
    EXPECT_EQ(parseReal("layer_height", "0.1"), 0.1);
    EXPECT_EQ(parseReal("layer_height", "1e-3"), 0.001);
    EXPECT_EQ(parseReal("layer_height", "2.99792458e+11"), 2.99792458e+11);
    EXPECT_EQ(parseReal("layer_height", "-2.5"), -2.5);
    EXPECT_EQ(parseReal("layer_height", "+3"), 3.0);
    EXPECT_EQ(parseReal("layer_height", " 7 "), 7.0);
}

TEST(ValueParse, RealRejectsNonNumbersNamingKeyAndValue) {
    for (const char* text : {"abc", "nan", "inf", "-inf", "", "1.2.3", "0.4mm", "0,4"}) {
        const std::string message = inputErrorOf([&] { parseReal("wall_thickness", text); });
        EXPECT_TRUE(contains(message, "wall_thickness")) << text << ": " << message;
        EXPECT_TRUE(contains(message, "'" + std::string(text) + "'")) << text << ": " << message;
    }
}

TEST(ValueParse, Integers) {
    EXPECT_EQ(parseInteger("wall_line_count", "3"), 3);
    EXPECT_EQ(parseInteger("wall_line_count", "3.0"), 3);
    EXPECT_EQ(parseInteger("support_extruder_nr", "-1"), -1);
    EXPECT_TRUE(contains(inputErrorOf([] { parseInteger("wall_line_count", "three"); }), "wall_line_count"));
}

TEST(ValueParse, LengthsAreRoundedToMicrons) {
    EXPECT_EQ(parseLengthMicrons("line_width", "0.1"), 100);
    EXPECT_EQ(parseLengthMicrons("line_width", "0.0004"), 0);
    EXPECT_EQ(parseLengthMicrons("line_width", "0.0006"), 1);
    EXPECT_EQ(parseLengthMicrons("line_width", "-0.2"), -200);
    EXPECT_EQ(parseLengthMicrons("machine_width", "235"), 235'000);
    EXPECT_EQ(parseLengthMicrons("machine_width", "1e-3"), 1);
}

TEST(ValueParse, RatioIsPercent) {
    EXPECT_EQ(parseRatio("infill_sparse_density", "50"), 0.5);
    EXPECT_EQ(parseRatio("infill_sparse_density", "100"), 1.0);
    EXPECT_EQ(parseRatio("infill_sparse_density", "12.5"), 0.125);
}

TEST(ValueParse, OnePolygonInMicrons) {
    const Path path = parsePolygonMicrons("machine_head_polygon", "[[-20, 10], [10, 10], [10, -10]]");
    const Path expected{{-20'000, 10'000}, {10'000, 10'000}, {10'000, -10'000}};
    EXPECT_EQ(path, expected);
    EXPECT_EQ(parsePolygonMicrons("p", "[[0.1, -0.25]]"), (Path{{100, -250}}));
    EXPECT_TRUE(parsePolygonMicrons("p", "[]").empty());
}

TEST(ValueParse, SeveralPolygonsInMicrons) {
    const Paths paths = parsePolygonsMicrons("machine_disallowed_areas",
                                             "[[[0, 0], [1, 0], [1, 1]], [[-2, -2], [-3, -2], [-3, -3.5]]]");
    ASSERT_EQ(paths.size(), 2U);
    EXPECT_EQ(paths[0], (Path{{0, 0}, {1000, 0}, {1000, 1000}}));
    EXPECT_EQ(paths[1], (Path{{-2000, -2000}, {-3000, -2000}, {-3000, -3500}}));
    EXPECT_TRUE(parsePolygonsMicrons("machine_disallowed_areas", "[]").empty());
}

TEST(ValueParse, MalformedPolygonsNameKeyAndValue) {
    for (const char* text :
         {"[[1, 2, 3]]", "[[1, 2], [3]]", "[[1, 2]", "[[a, b]]", "[1, 2]", "5", "[[1, 2]] x"}) {
        const std::string message = inputErrorOf([&] { parsePolygonMicrons("machine_head_polygon", text); });
        EXPECT_TRUE(contains(message, "machine_head_polygon")) << text << ": " << message;
        EXPECT_TRUE(contains(message, text)) << text << ": " << message;
    }
    // One polygon is not a list of polygons.
    EXPECT_TRUE(
        contains(inputErrorOf([] { parsePolygonsMicrons("areas", "[[-20, 10], [10, 10]]"); }), "areas"));
}

TEST(ValueParse, Matrix3RowMajor) {
    using Rows = std::array<std::array<double, 3>, 3>;
    EXPECT_EQ(parseMatrix3("mesh_rotation_matrix", "[[1,0,0],[0,1,0],[0,0,1]]"),
              (Rows{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}));
    EXPECT_EQ(parseMatrix3("mesh_rotation_matrix", "[[1, 2, 3], [4, 5, 6], [7, 8, 9.5]]"),
              (Rows{{{1, 2, 3}, {4, 5, 6}, {7, 8, 9.5}}}));
}

TEST(ValueParse, MalformedMatricesAreRejected) {
    for (const char* text : {"[[1,0],[0,1]]", "[[1,0,0],[0,1,0]]", "[[1,0,0],[0,1,0],[0,0,1],[0,0,0]]",
                             "[[1,0,0],[0,1,0],[0,0,[1]]]", "[[1,0,0],[0,1,0],[0,0,1,0]]", "1", "", "[1,0,0]",
                             "[[1,0,0],[0,1,0],[0,0,x]]"}) {
        const std::string message = inputErrorOf([&] { parseMatrix3("mesh_rotation_matrix", text); });
        EXPECT_TRUE(contains(message, "mesh_rotation_matrix")) << "'" << text << "': " << message;
    }
}

TEST(ValueParse, NestedListsWithSpacesTrailingCommasAndTuples) {
    const NumberTree tree = parseNumberTree("k", " [ [ 1 , 2 ] , [ 3 , 4.5 , ] , ] ");
    ASSERT_FALSE(tree.is_leaf);
    ASSERT_EQ(tree.children.size(), 2U);
    ASSERT_EQ(tree.children[1].children.size(), 2U);
    EXPECT_TRUE(tree.children[1].children[1].is_leaf);
    EXPECT_EQ(tree.children[1].children[1].number, 4.5);
    EXPECT_EQ(parseRealList("infill_angles", "[0, 90]"), (std::vector<double>{0, 90}));
    EXPECT_EQ(parseRealList("infill_angles", "[1, 2,]"), (std::vector<double>{1, 2}));
    EXPECT_EQ(parseRealList("infill_angles", "(45, 135)"), (std::vector<double>{45, 135}));
    EXPECT_EQ(parseRealList("infill_angles", "[ ]"), (std::vector<double>{}));
    for (const char* text : {"[,]", "[1,,2]", "[1 2]", "5", "[[1]]", "[1, 2", "[1, 2]]"}) {
        const std::string message = inputErrorOf([&] { parseRealList("infill_angles", text); });
        EXPECT_TRUE(contains(message, "infill_angles")) << "'" << text << "': " << message;
    }
}

// The nesting is bounded (settings use 3 levels), so a long run of brackets cannot overflow the stack.
TEST(ValueParse, NestingDeeperThan32IsRejected) {
    const auto nested = [](int depth) { return std::string(depth, '[') + "1" + std::string(depth, ']'); };
    EXPECT_NO_THROW(parseNumberTree("k", nested(32)));
    EXPECT_TRUE(contains(inputErrorOf([&] { parseNumberTree("k", nested(33)); }), "nested at most 32 deep"));
    const std::string message = inputErrorOf([&] { parsePolygonsMicrons("areas", nested(1000000)); });
    EXPECT_TRUE(contains(message, "setting 'areas'")) << message.substr(0, 200);
}

TEST(Settings, TypedGettersCarryTheirUnit) {
    const Settings s("global settings", {{"speed_travel", "25"},
                                         {"layer_height", "0.8"},
                                         {"infill_material_flow", "20"},
                                         {"support_angle", "90"},
                                         {"adhesion_extruder_nr", "-1"},
                                         {"mesh_rotation_matrix", "[[0, -1, 0], [1, 0, 0], [0, 0, 2]]"}});
    EXPECT_EQ(s.velocityMmPerS(key::speed_travel), 25.0);
    EXPECT_EQ(s.lengthMicrons(key::layer_height), 800);
    EXPECT_EQ(s.millimetres(key::layer_height), 0.8);
    EXPECT_EQ(s.ratio(key::infill_material_flow), 0.2);
    EXPECT_EQ(s.percent(key::infill_material_flow), 20.0);
    EXPECT_EQ(s.angleDegrees(key::support_angle), 90.0);
    EXPECT_DOUBLE_EQ(s.angleRadians(key::support_angle), std::numbers::pi / 2);
    EXPECT_EQ(s.extruderIndex(key::adhesion_extruder_nr), -1);
    const Matrix3 m = s.matrix3(key::mesh_rotation_matrix);
    EXPECT_EQ(m.m[0][1], -1.0);
    EXPECT_EQ(m.m[1][0], 1.0);
    EXPECT_EQ(m.m[2][2], 2.0);
    const Vec3 p = m.apply({1, 2, 3});
    EXPECT_EQ(p, (Vec3{-2, 1, 6}));
}

TEST(Settings, MissingKeyNamesKeyAndScope) {
    const Settings s("extruder 1", {{"layer_height", "0.1"}});
    EXPECT_FALSE(s.has(key::speed_travel));
    for (const auto& call : {std::function<void()>([&] { s.text(key::speed_travel); }),
                             std::function<void()>([&] { s.velocityMmPerS(key::speed_travel); }),
                             std::function<void()>([&] { s.boolean(key::magic_spiralize); })}) {
        const std::string message = inputErrorOf(call);
        EXPECT_TRUE(contains(message, "speed_travel") || contains(message, "magic_spiralize")) << message;
        EXPECT_TRUE(contains(message, "extruder 1")) << message;
    }
}

TEST(Settings, MalformedValueNamesKeyAndValue) {
    const Settings s("global settings", {{"layer_height", "abc"}, {"infill_angles", "[1, x]"}});
    std::string message = inputErrorOf([&] { s.lengthMicrons(key::layer_height); });
    EXPECT_TRUE(contains(message, "layer_height") && contains(message, "abc")) << message;
    message = inputErrorOf([&] { s.realList(key::infill_angles); });
    EXPECT_TRUE(contains(message, "infill_angles") && contains(message, "[1, x]")) << message;
}

TEST(Settings, WithOverlaysACopy) {
    const Settings base("global settings", {{"a", "1"}, {"b", "2"}});
    const Settings group = base.with("mesh group 0", {{"b", "3"}, {"c", "4"}});
    EXPECT_EQ(group.scope(), "mesh group 0");
    EXPECT_EQ(group.all().at("a"), "1");
    EXPECT_EQ(group.all().at("b"), "3");
    EXPECT_EQ(group.all().at("c"), "4");
    EXPECT_EQ(group.all().size(), 3U);
    EXPECT_EQ(base.all().at("b"), "2");
    EXPECT_EQ(base.find("c"), nullptr);
    EXPECT_EQ(base.scope(), "global settings");
}

}  // namespace
}  // namespace mixengine
