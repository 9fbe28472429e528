// Skirt and brim (toolpaths/adhesion/Adhesion.h) around squares, with fdmprinter's resolved settings.
#include "toolpaths/adhesion/Adhesion.h"

#include <gtest/gtest.h>

#include <numbers>

#include "ToolpathTestSupport.h"
#include "geometry/PolygonOps.h"

namespace mixengine {
namespace {

using test::square;

AdhesionResult adhesion(const SettingValues& user, const Paths& models, const Paths& extras = {}) {
    const ResolvedMachine m = test::fdmMachine(user);
    return generateAdhesion({&m.global, &m.extruders, models, extras, {}});
}

/// Distance from the square's edge to a loop around it: half the loop's bounding-box growth.
coord_um distanceOut(const ExtrusionPath& loop, coord_um x0, coord_um size) {
    const ClipperLib::IntRect box = boundsOf({loop.points});
    EXPECT_EQ(x0 - box.left, box.right - (x0 + size));
    return x0 - box.left;
}

TEST(Adhesion, BrimLineCountAndSpacing) {
    const AdhesionResult r =
        adhesion({{"adhesion_type", "brim"}, {"brim_width", "2"}, {"skirt_brim_minimal_length", "0"}},
                 {square(0, 0, 20'000)});
    // brim_line_count = ceil(2 / 0.4) = 5 loops, 0.2, 0.6, … 1.8 mm out, printed outermost first.
    ASSERT_EQ(r.paths.size(), 5U);
    for (std::size_t i = 0; i < 5; ++i) {
        EXPECT_EQ(distanceOut(r.paths[i], 0, 20'000), coord_um(1'800 - 400 * i)) << i;
        EXPECT_EQ(r.paths[i].feature, Feature::Skirt);
        EXPECT_TRUE(r.paths[i].closed);
        EXPECT_EQ(r.paths[i].width_um, 400);
        EXPECT_EQ(r.paths[i].speed_mm_s, 30.0);  // skirt_brim_speed
    }
    EXPECT_TRUE(r.warnings.empty());
}

TEST(Adhesion, BrimGapAndHoles) {
    Path hole = square(5'000, 5'000, 10'000);
    std::reverse(hole.begin(), hole.end());
    const SettingValues base{{"adhesion_type", "brim"},
                             {"brim_line_count", "2"},
                             {"brim_gap", "0.5"},
                             {"skirt_brim_minimal_length", "0"}};
    const AdhesionResult outside = adhesion(base, {square(0, 0, 20'000), hole});
    ASSERT_EQ(outside.paths.size(), 2U);
    EXPECT_EQ(distanceOut(outside.paths[1], 0, 20'000), 700);  // gap + half a line
    SettingValues inside = base;
    inside["brim_outside_only"] = "False";
    EXPECT_EQ(adhesion(inside, {square(0, 0, 20'000), hole}).paths.size(), 4U);  // also in the hole
}

TEST(Adhesion, BrimLeavesOutHolesUnderAHundredLineWidthsSquared) {
    // As CuraEngine's SkirtBrim: a 3 mm hole's brim loops (2.6 mm and less across, under 16 mm²) are left
    // out, a 10 mm hole's are printed.
    const SettingValues values{{"adhesion_type", "brim"},
                               {"brim_line_count", "2"},
                               {"brim_outside_only", "False"},
                               {"skirt_brim_minimal_length", "0"}};
    Path small = square(8'500, 8'500, 3'000);
    std::reverse(small.begin(), small.end());
    EXPECT_EQ(adhesion(values, {square(0, 0, 20'000), small}).paths.size(), 2U);
    Path large = square(5'000, 5'000, 10'000);
    std::reverse(large.begin(), large.end());
    EXPECT_EQ(adhesion(values, {square(0, 0, 20'000), large}).paths.size(), 4U);
}

TEST(Adhesion, BrimGapJoinsNeighboursAndDropsTheEmptyHoleBetween) {
    // Two 10 mm squares 1 mm apart with a 0.6 mm gap: grown by the gap they overlap, so one brim goes around
    // both (two loops), none between them.
    const SettingValues values{{"adhesion_type", "brim"},
                               {"brim_line_count", "2"},
                               {"brim_gap", "0.6"},
                               {"skirt_brim_minimal_length", "0"}};
    EXPECT_EQ(adhesion(values, {square(0, 0, 10'000), square(11'000, 0, 10'000)}).paths.size(), 2U);
}

TEST(Adhesion, SkirtDistanceAndMinimalLength) {
    const AdhesionResult one = adhesion({{"adhesion_type", "skirt"},
                                         {"skirt_gap", "3"},
                                         {"skirt_line_count", "1"},
                                         {"skirt_brim_minimal_length", "0"}},
                                        {square(0, 0, 20'000)});
    ASSERT_EQ(one.paths.size(), 1U);
    EXPECT_EQ(distanceOut(one.paths[0], 0, 20'000), 3'200);
    // 250 mm at least: loops of ~105 mm, so three of them (as CuraEngine prints on a 20 mm cube).
    const AdhesionResult three = adhesion({{"adhesion_type", "skirt"},
                                           {"skirt_gap", "3"},
                                           {"skirt_line_count", "1"},
                                           {"skirt_brim_minimal_length", "250"}},
                                          {square(0, 0, 20'000)});
    EXPECT_EQ(three.paths.size(), 3U);
    EXPECT_EQ(distanceOut(three.paths[0], 0, 20'000), 4'000);
}

TEST(Adhesion, SkirtGoesAroundTheHullOfEverything) {
    const AdhesionResult r =
        adhesion({{"adhesion_type", "skirt"}, {"skirt_gap", "1"}, {"skirt_brim_minimal_length", "0"}},
                 {square(0, 0, 10'000), square(30'000, 0, 10'000)}, {square(15'000, 20'000, 1'000)});
    ASSERT_EQ(r.paths.size(), 1U);  // one loop around both squares and the extra point set
    const ClipperLib::IntRect box = boundsOf({r.paths[0].points});
    EXPECT_EQ(box.left, -1'200);
    EXPECT_EQ(box.right, 41'200);
    EXPECT_EQ(box.bottom, 22'200);
}

TEST(Adhesion, LoopsAreSimplifiedWithTheMaximumResolution) {
    // A skirt around a square has round corners of 10 µm arcs' segments: 0.5 mm segments keep fewer
    // of their vertices than 0.01 mm ones (CuraEngine 4.13 simplifies skirt and brim so).
    const ResolvedMachine fine = test::fdmMachine({{"adhesion_type", "skirt"},
                                                   {"skirt_gap", "3"},
                                                   {"skirt_brim_minimal_length", "0"},
                                                   {"meshfix_maximum_resolution", "0.01"}});
    const ResolvedMachine coarse = test::fdmMachine({{"adhesion_type", "skirt"},
                                                     {"skirt_gap", "3"},
                                                     {"skirt_brim_minimal_length", "0"},
                                                     {"meshfix_maximum_resolution", "2"},
                                                     {"meshfix_maximum_deviation", "0.1"}});
    std::vector<ExtrusionPath> a =
        generateAdhesion({&fine.global, &fine.extruders, {square(0, 0, 20'000)}, {}, {}}).paths;
    std::vector<ExtrusionPath> b = a;
    simplifyAdhesion(fine.global, &fine.extruders, a);
    simplifyAdhesion(coarse.global, &coarse.extruders, b);
    ASSERT_EQ(a.size(), 1U);
    ASSERT_EQ(b.size(), 1U);
    EXPECT_LT(b[0].points.size(), a[0].points.size());
    EXPECT_GE(b[0].points.size(), 4U);
}

TEST(Adhesion, NoneAndRaft) {
    EXPECT_TRUE(adhesion({{"adhesion_type", "none"}}, {square(0, 0, 10'000)}).paths.empty());
    // A raft is no skirt: toolpaths/adhesion/Raft.h builds it, nothing here and no warning.
    const AdhesionResult raft = adhesion({{"adhesion_type", "raft"}}, {square(0, 0, 10'000)});
    EXPECT_TRUE(raft.paths.empty());
    EXPECT_TRUE(raft.warnings.empty());
}

TEST(Adhesion, ConvexHull) {
    const Path hull = convexHull({{{0, 0}, {10, 0}, {10, 10}, {5, 2}, {0, 10}}});
    EXPECT_EQ(hull, (Path{{0, 0}, {10, 0}, {10, 10}, {0, 10}}));
}

}  // namespace
}  // namespace mixengine
