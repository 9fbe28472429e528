// Skin paths of one layer (toolpaths/skin/SkinPaths.h): loops, roofing inside them, skin, monotonic
// sequences and the gaps of concentric skin.
#include "toolpaths/skin/SkinPaths.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "ToolpathTestSupport.h"
#include "geometry/PolygonOps.h"

namespace mixengine {
namespace {

using test::rect;
using test::square;

FeatureStyle style(double speed_mm_s, coord_um width_um = 400) {
    return {width_um, speed_mm_s, 1.0, 0};
}

SkinPathParams params() {
    SkinPathParams p;
    p.outline_count = 1;
    p.skin.style = style(20);
    p.skin.overlap_um = 40;
    p.roofing.style = style(25);
    return p;
}

std::vector<ExtrusionPath> withSpeed(const std::vector<ExtrusionPath>& paths, double speed, bool closed) {
    std::vector<ExtrusionPath> out;
    std::copy_if(paths.begin(), paths.end(), std::back_inserter(out),
                 [&](const ExtrusionPath& p) { return p.speed_mm_s == speed && p.closed == closed; });
    return out;
}

coord_um extent(const std::vector<ExtrusionPath>& paths, bool max_x) {
    coord_um x = max_x ? INT64_MIN : INT64_MAX;
    for (const ExtrusionPath& p : paths)
        for (const Point2& q : p.points)
            x = max_x ? std::max(x, q.X) : std::min(x, q.X);
    return x;
}

TEST(SkinPaths, RoofingIsFilledInsideTheSkinLoopsWithoutOverlap) {
    // A 20 mm square whose left half has air above.
    const Paths skin{square(0, 0, 20'000)};
    const Paths roofing{rect(-1'000, -1'000, 10'000, 21'000)};
    const std::vector<ExtrusionPath> paths = generateSkinPaths(skin, roofing, params());
    // One loop around the whole part, in the skin style, 0.19 mm inside (half a line less 10 µm).
    const std::vector<ExtrusionPath> loops = withSpeed(paths, 20, true);
    ASSERT_EQ(loops.size(), 1U);
    EXPECT_EQ(extent(loops, false), 190);
    EXPECT_TRUE(withSpeed(paths, 25, true).empty());
    // Roofing lines in the left half of the fill area (x 0.39 … 10 mm, no overlap), skin lines in
    // the right half grown by the 0.04 mm overlap.
    const std::vector<ExtrusionPath> roof = withSpeed(paths, 25, false), rest = withSpeed(paths, 20, false);
    ASSERT_FALSE(roof.empty());
    ASSERT_FALSE(rest.empty());
    EXPECT_GE(extent(roof, false), 390);
    EXPECT_LE(extent(roof, true), 10'000);
    EXPECT_GE(extent(rest, false), 10'000 - 40);
    EXPECT_LE(extent(rest, true), 20'000 - 390 + 40);
    // Printed in CuraEngine's order: the loop, the roofing, the skin.
    EXPECT_TRUE(paths.front().closed);
    EXPECT_EQ(paths[1].speed_mm_s, 25.0);
    EXPECT_EQ(paths.back().speed_mm_s, 20.0);
}

TEST(SkinPaths, RoofingLinesAreTheRoofingFeatureTheRestSkin) {
    SkinPathParams p = params();
    p.roofing.feature = Feature::Roofing;  // as the mesh's toolpaths set it (own acceleration and jerk)
    const std::vector<ExtrusionPath> paths =
        generateSkinPaths({square(0, 0, 20'000)}, {rect(-1'000, -1'000, 10'000, 21'000)}, p);
    ASSERT_FALSE(paths.empty());
    for (const ExtrusionPath& path : paths)
        EXPECT_EQ(path.feature, path.speed_mm_s == 25 ? Feature::Roofing : Feature::Skin);
    EXPECT_EQ(featureMarker(Feature::Roofing), "SKIN");
}

TEST(SkinPaths, MonotonicLinesAreOneSequencePerFill) {
    SkinPathParams p = params();
    p.skin.monotonic = true;
    p.skin.angle_degrees = 0;  // lines along Y, printed from the right
    const std::vector<ExtrusionPath> paths = generateSkinPaths({square(0, 0, 10'000)}, {}, p);
    std::vector<coord_um> xs;
    for (const ExtrusionPath& path : paths) {
        if (path.closed) {
            EXPECT_EQ(path.sequence, 0U);
            continue;
        }
        EXPECT_EQ(path.sequence, 1U);
        xs.push_back(path.points.front().X);
    }
    ASSERT_GT(xs.size(), 10U);
    EXPECT_TRUE(std::is_sorted(xs.rbegin(), xs.rend()));
    p.skin.monotonic = false;
    for (const ExtrusionPath& path : generateSkinPaths({square(0, 0, 10'000)}, {}, p))
        EXPECT_EQ(path.sequence, 0U);
}

TEST(SkinPaths, ConcentricSkinHasNoOutlineLoopsAndItsGapsAreFilled) {
    SkinPathParams p = params();
    p.skin.pattern = InfillPattern::Concentric;
    p.gap_style = style(20, 200);
    // 10.62 mm wide: loops 0.16 mm in (half a line less the overlap), then every 0.4 mm; the last is
    // 0.7 mm wide, and the 0.27 mm left in its middle is a gap for lines half a wall line wide.
    const std::vector<ExtrusionPath> paths = generateSkinPaths({square(0, 0, 10'620)}, {}, p);
    const auto loops =
        std::count_if(paths.begin(), paths.end(), [](const ExtrusionPath& q) { return q.closed; });
    const auto gap_lines = std::count_if(
        paths.begin(), paths.end(), [](const ExtrusionPath& q) { return !q.closed && q.width_um == 200; });
    EXPECT_EQ(loops, 13);
    EXPECT_GT(gap_lines, 0);
    EXPECT_EQ(extent(paths, false), 160);
    p.gap_style.reset();  // fill_perimeter_gaps = nowhere
    for (const ExtrusionPath& path : generateSkinPaths({square(0, 0, 10'620)}, {}, p))
        EXPECT_TRUE(path.closed);
}

TEST(SkinPaths, EachIslandIsAPartWithItsOwnLoop) {
    const Paths skin{square(0, 0, 5'000), square(10'000, 0, 5'000)};
    const std::vector<ExtrusionPath> paths = generateSkinPaths(skin, {}, params());
    EXPECT_EQ(std::count_if(paths.begin(), paths.end(), [](const ExtrusionPath& q) { return q.closed; }), 2);
}

TEST(SkinPaths, EachIslandIsNumberedAndItsPathsStaged) {
    SkinPathParams p = params();
    p.skin.pattern = InfillPattern::Concentric;
    p.gap_style = style(20, 200);
    const Paths skin{square(0, 0, 10'620), square(20'000, 0, 5'000)};
    const std::vector<ExtrusionPath> paths = generateSkinPaths(skin, {}, p);
    p.skin.pattern = InfillPattern::Lines;
    const std::vector<ExtrusionPath> lines = generateSkinPaths(skin, {}, p);
    // Concentric (no outline loops): the fill's loops are stage 3, the lines in their gaps stage 4.
    for (const ExtrusionPath& path : paths) {
        EXPECT_EQ(path.skin_part, path.points.front().X < 15'000 ? 1U : 2U);
        EXPECT_EQ(path.skin_stage, path.closed ? 3 : 4);
    }
    // Lines: each part's outline loop is stage 1, its lines stage 3.
    for (const ExtrusionPath& path : lines) {
        EXPECT_EQ(path.skin_part, path.points.front().X < 15'000 ? 1U : 2U);
        EXPECT_EQ(path.skin_stage, path.closed ? 1 : 3);
    }
}

TEST(SkinPaths, LinesStartLookingFromTheAreaCornersAcrossTheirDirection) {
    // A 10 mm square skin: its loop 0.19 mm in, the fill area 0.2 mm further in (0.39 … 9.61 mm).
    // Lines at 45°: CuraEngine looks from far out across them, at the top left and the bottom right
    // of the fill area's box, and takes its corners nearest to those points.
    SkinPathParams p = params();
    p.skin.angle_degrees = 45;
    const std::vector<ExtrusionPath> paths = generateSkinPaths({square(0, 0, 10'000)}, {}, p);
    const std::array<Point2, 2> expected{Point2{390, 9'610}, Point2{9'610, 390}};
    std::size_t lines = 0;
    for (const ExtrusionPath& path : paths) {
        if (path.closed) {
            EXPECT_FALSE(path.seam_avoiding_starts);
            continue;
        }
        ++lines;
        ASSERT_TRUE(path.seam_avoiding_starts);
        EXPECT_EQ(*path.seam_avoiding_starts, expected);
    }
    EXPECT_GT(lines, 0U);
    // Monotonic lines and concentric fills start from the head.
    p.skin.monotonic = true;
    for (const ExtrusionPath& path : generateSkinPaths({square(0, 0, 10'000)}, {}, p))
        EXPECT_FALSE(path.seam_avoiding_starts);
}

}  // namespace
}  // namespace mixengine
