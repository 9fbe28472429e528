// A part's skin group in print order (planning/order/SkinOrder.h): skin part by skin part, nearest
// first, each stage by stage; lines of no skin part before (outline gaps) and after (perimeter gaps).
#include "planning/order/SkinOrder.h"

#include <gtest/gtest.h>

namespace mixengine {
namespace {

ExtrusionPath skinPath(Path points, std::uint32_t part, std::uint8_t stage, bool closed = false) {
    ExtrusionPath p;
    p.points = std::move(points);
    p.closed = closed;
    p.skin_part = part;
    p.skin_stage = stage;
    return p;
}

Path square(coord_um x, coord_um y, coord_um size) {
    return {{x, y}, {x + size, y}, {x + size, y + size}, {x, y + size}};
}

TEST(SkinOrder, SkinPartsPrintTogetherStageByStageNearestFirst) {
    // Listed: an outline gap line, skin part 1 at x 30 mm (its lines before its loop), skin part 2
    // at x 0 (lines, gap lines, loop), a perimeter gap line.
    std::vector<ExtrusionPath> paths{
        skinPath({{20'000, 0}, {21'000, 0}}, 0, 0),       skinPath({{31'000, 1'000}, {39'000, 1'000}}, 1, 3),
        skinPath(square(30'000, 0, 10'000), 1, 1, true),  skinPath({{1'000, 1'000}, {9'000, 1'000}}, 2, 3),
        skinPath({{1'000, 2'000}, {9'000, 2'000}}, 2, 3), skinPath({{1'000, 5'000}, {2'000, 5'000}}, 2, 4),
        skinPath(square(0, 0, 10'000), 2, 1, true),       skinPath({{22'000, 0}, {23'000, 0}}, 0, 0),
    };
    const std::vector<std::vector<ExtrusionPath>> groups = skinPrintGroups(paths, {-1'000, 0});
    ASSERT_EQ(groups.size(), 7U);
    EXPECT_EQ(groups[0].front().points.front(), (Point2{20'000, 0}));  // the outline gap first
    // Part 2 (its loop has the vertex nearest to the head): loop, lines, gap lines.
    EXPECT_TRUE(groups[1].front().closed);
    EXPECT_EQ(groups[1].front().skin_part, 2U);
    EXPECT_EQ(groups[2].size(), 2U);
    EXPECT_EQ(groups[2].front().skin_stage, 3);
    EXPECT_EQ(groups[3].front().skin_stage, 4);
    // Then part 1: loop, lines; the perimeter gap last.
    EXPECT_EQ(groups[4].front().skin_part, 1U);
    EXPECT_TRUE(groups[4].front().closed);
    EXPECT_EQ(groups[5].front().skin_stage, 3);
    EXPECT_EQ(groups[6].front().points.front(), (Point2{22'000, 0}));
}

TEST(SkinOrder, PartsAreOrderedFromTheVertexChosenNotFromWhereTheyEnd) {
    // From the head at the origin: part 1 (vertex at 5 mm) first; from its vertex (5, 0) part 3
    // (vertex at 8 mm) is nearer than part 2 (vertex at 0, 9 mm), however far part 1's lines reach.
    std::vector<ExtrusionPath> paths{
        skinPath({{5'000, 0}, {5'000, 20'000}}, 1, 3),
        skinPath({{0, 9'000}, {0, 9'500}}, 2, 3),
        skinPath({{8'000, 0}, {8'500, 0}}, 3, 3),
    };
    const std::vector<std::vector<ExtrusionPath>> groups = skinPrintGroups(paths, {0, 0});
    ASSERT_EQ(groups.size(), 3U);
    EXPECT_EQ(groups[0].front().skin_part, 1U);
    EXPECT_EQ(groups[1].front().skin_part, 3U);
    EXPECT_EQ(groups[2].front().skin_part, 2U);
}

TEST(SkinOrder, LoopsGoNearestVertexFirst) {
    // Loop 0 (x 0 … 10 mm) is listed from its far corner, but its corner (10, 10) mm lies 0.8 mm
    // from the head; loop 1's nearest corner (12, 10) mm 1.2 mm, its first point 2.3 mm. From loop
    // 0's corner loop 1 is 2 mm away, loop 2 (at y 20 mm) 10 mm.
    std::vector<ExtrusionPath> loops{
        skinPath({{0, 0}, {10'000, 0}, {10'000, 10'000}, {0, 10'000}}, 1, 1, true),
        skinPath({{12'000, 12'000}, {12'000, 10'000}, {14'000, 10'000}, {14'000, 12'000}}, 1, 1, true),
        skinPath(square(10'000, 20'000, 1'000), 1, 1, true),
    };
    const std::vector<ExtrusionPath> ordered = loopsNearestFirst(loops, {10'800, 10'000});
    ASSERT_EQ(ordered.size(), 3U);
    EXPECT_EQ(ordered[0].points.front(), (Point2{0, 0}));
    EXPECT_EQ(ordered[1].points.front(), (Point2{12'000, 12'000}));
    EXPECT_EQ(ordered[2].points.front(), (Point2{10'000, 20'000}));
}

TEST(SkinOrder, WithoutSkinPartsEverythingIsOneGroup) {
    std::vector<ExtrusionPath> paths{skinPath({{0, 0}, {1'000, 0}}, 0, 0),
                                     skinPath({{5'000, 0}, {6'000, 0}}, 0, 0)};
    const std::vector<std::vector<ExtrusionPath>> groups = skinPrintGroups(paths, {0, 0});
    ASSERT_EQ(groups.size(), 1U);
    EXPECT_EQ(groups[0].size(), 2U);
    EXPECT_TRUE(skinPrintGroups({}, {0, 0}).empty());
}

}  // namespace
}  // namespace mixengine
