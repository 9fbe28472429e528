// Top/bottom skin areas (toolpaths/skin/Skin.h) on stacks of squares.
#include "toolpaths/skin/Skin.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "ToolpathTestSupport.h"
#include "geometry/PolygonOps.h"

namespace mixengine {
namespace {

Paths sq(coord_um x0, coord_um size) {
    return {test::square(x0, x0, size)};
}

SkinParams layersOnly(int top, int bottom) {
    SkinParams p;
    p.top_layers = top;
    p.bottom_layers = bottom;
    p.initial_bottom_layers = bottom;
    return p;
}

std::vector<SkinAreas> skins(const std::vector<Paths>& areas, const SkinParams& p, int threads = 1) {
    return computeSkinAreas({&areas, &areas, nullptr}, areas, p, threads);
}

TEST(Skin, StackOfIdenticalSquares) {
    const std::vector<Paths> areas(6, sq(0, 10'000));
    for (int threads : {1, 2}) {
        const std::vector<SkinAreas> s = skins(areas, layersOnly(2, 2), threads);
        ASSERT_EQ(s.size(), 6U);
        for (int layer : {0, 1, 4, 5}) {
            EXPECT_EQ(areaUm2(s[layer].skin), 100e6) << layer;
            EXPECT_TRUE(s[layer].infill.empty()) << layer;
        }
        for (int layer : {2, 3}) {
            EXPECT_TRUE(s[layer].skin.empty()) << layer;
            EXPECT_EQ(areaUm2(s[layer].infill), 100e6) << layer;
        }
    }
}

TEST(Skin, NoTopOrBottomLayersNoSkin) {
    const std::vector<Paths> areas(4, sq(0, 10'000));
    for (const SkinAreas& s : skins(areas, layersOnly(0, 0)))
        EXPECT_TRUE(s.skin.empty());
    const std::vector<SkinAreas> only_top = skins(areas, layersOnly(1, 0));
    EXPECT_TRUE(only_top[0].skin.empty());
    EXPECT_EQ(areaUm2(only_top[3].skin), 100e6);
}

TEST(Skin, SolidInfillThroughHugeBottomCount) {
    // infill_sparse_density 100 resolves to bottom_layers 999999: everything is skin, and cheaply.
    const std::vector<Paths> areas(50, sq(0, 10'000));
    for (const SkinAreas& s : skins(areas, layersOnly(0, 999'999))) {
        EXPECT_EQ(areaUm2(s.skin), 100e6);
        EXPECT_TRUE(s.infill.empty());
    }
}

TEST(Skin, SmallerSquareOnTopLeavesARing) {
    std::vector<Paths> areas(3, sq(0, 20'000));
    for (int i = 0; i < 3; ++i)
        areas.push_back(sq(5'000, 10'000));
    const std::vector<SkinAreas> s = skins(areas, layersOnly(1, 1));
    EXPECT_EQ(areaUm2(s[0].skin), 400e6);  // bottom layer
    EXPECT_TRUE(s[1].skin.empty());
    EXPECT_EQ(areaUm2(s[2].skin), 400e6 - 100e6);  // the ring not covered by the square above
    EXPECT_EQ(areaUm2(s[2].infill), 100e6);
    EXPECT_TRUE(s[3].skin.empty());  // fully supported by the big square below
    EXPECT_EQ(areaUm2(s[5].skin), 100e6);
}

TEST(Skin, RemovalWidthDropsNarrowStripsAndExpansionGrowsIntoInfill) {
    // Layer 1's square is 1 mm bigger on each side than layer 2's: a 1 mm top-skin ring.
    const std::vector<Paths> areas{sq(0, 20'000), sq(0, 20'000), sq(1'000, 18'000), sq(1'000, 18'000)};
    SkinParams p = layersOnly(1, 0);
    p.top_preshrink_um = 1'100;  // removes strips narrower than 1.1 mm: the ring goes
    EXPECT_TRUE(skins(areas, p)[1].skin.empty());
    p.top_preshrink_um = 900;  // keeps it
    EXPECT_EQ(areaUm2(skins(areas, p)[1].skin), 400e6 - 324e6);
    p.top_expand_um = 500;  // and grows it 0.5 mm into the infill (not beyond the inner area)
    const SkinAreas grown = skins(areas, p)[1];
    EXPECT_EQ(areaUm2(grown.skin), 400e6 - 17'000.0 * 17'000.0);
    EXPECT_EQ(areaUm2(grown.infill), 17'000.0 * 17'000.0);
}

TEST(Skin, RemovalWidthCountsFromTheCoveredAreaOnly) {
    // Layer 1: two 10 mm squares joined by a 0.15 mm wide, 4 mm long neck; layer 2 covers the
    // squares only. The neck has air above: it is top skin although narrower than the removal
    // width, which takes 0.2 mm off it along the covered squares alone, given back by the expansion.
    const Paths squares{test::square(0, 0, 10'000), test::square(14'000, 0, 10'000)};
    const Paths neck{{{10'000, 4'925}, {14'000, 4'925}, {14'000, 5'075}, {10'000, 5'075}}};
    const std::vector<Paths> areas{unionOf(squares, neck), unionOf(squares, neck), squares};
    SkinParams p = layersOnly(1, 0);
    p.top_preshrink_um = 200;
    EXPECT_NEAR(areaUm2(skins(areas, p)[1].skin), areaUm2(neck), 1e3);
    // Grown 0.4 mm (plus the 0.2 mm given back) into each square: 0.4 mm deep, 0.15 + 2 × 0.6 mm wide.
    p.top_expand_um = 400;
    const SkinAreas s = skins(areas, p)[1];
    EXPECT_NEAR(areaUm2(intersectAll(s.skin, neck)), areaUm2(neck), 1e3);
    EXPECT_NEAR(areaUm2(intersectAll(s.skin, {test::square(0, 0, 10'000)})), 400.0 * 1'350, 0.05 * 540e3);
}

TEST(Skin, SmallAreaRemovalCountsTheOutlineWithoutItsHoles) {
    // A 0.5 mm square frame around a 0.4 mm hole: 0.09 mm² of skin, but its outline holds 0.25 mm²
    // (over CuraEngine's 0.16 mm²): kept whole, hole and all. A 0.3 mm square (0.09 mm²) goes.
    Path hole = test::square(50, 50, 400);
    std::reverse(hole.begin(), hole.end());
    const Paths frame{test::square(0, 0, 500), hole};
    const SkinAreas kept = skins({frame}, layersOnly(0, 1))[0];
    EXPECT_EQ(areaUm2(kept.skin), 500.0 * 500 - 400.0 * 400);
    EXPECT_TRUE(skins({sq(0, 300)}, layersOnly(0, 1))[0].skin.empty());
}

TEST(Skin, MinInfillAreaDropsSmallCoveringPieces) {
    // Layer 1 is covered by a 1 mm square on layer 2 only: top skin around it; with min_infill_area
    // 2 mm² that piece does not count as cover and all of layer 1 is skin.
    const std::vector<Paths> areas{sq(0, 20'000), sq(0, 20'000), sq(5'000, 1'000)};
    SkinParams p = layersOnly(1, 0);
    EXPECT_EQ(areaUm2(skins(areas, p)[1].skin), 400e6 - 1e6);
    EXPECT_EQ(areaUm2(skins(areas, p)[1].infill), 1e6);
    p.min_infill_area_um2 = 2e6;
    EXPECT_EQ(areaUm2(skins(areas, p)[1].skin), 400e6);
    EXPECT_TRUE(skins(areas, p)[1].infill.empty());
}

TEST(Skin, SmallGapsHeuristicComparesWithTheFarthestLayerOnly) {
    // Layer 2 has a 2 mm hole that layers 1 and 3 do not: the intersection over layers 2-3 (top
    // skin of layer 1) and over layers 1-2 (bottom skin of layer 3) has the hole, so both get skin
    // there; with the heuristic only layer 3 (for layer 1's top) and layer 1 (for layer 3's bottom)
    // count, and neither gets any.
    Path hole = test::square(9'000, 9'000, 2'000);
    std::reverse(hole.begin(), hole.end());
    const Paths holed{test::square(0, 0, 20'000), hole};
    std::vector<Paths> areas(7, sq(0, 20'000));
    areas[2] = holed;
    SkinParams p = layersOnly(2, 2);
    p.initial_bottom_layers = 1;
    EXPECT_EQ(areaUm2(skins(areas, p)[1].skin), 4e6);
    EXPECT_EQ(areaUm2(skins(areas, p)[3].skin), 4e6);
    p.small_gaps_heuristic = true;
    EXPECT_TRUE(skins(areas, p)[1].skin.empty());
    EXPECT_TRUE(skins(areas, p)[3].skin.empty());
    EXPECT_EQ(areaUm2(skins(areas, p)[6].skin), 400e6);  // the top layer
}

TEST(Skin, ReferenceWallMovesOutWithTheRemovalWidth) {
    // Two walls of 0.4 mm: the innermost centre region is the reference until the removal width
    // covers 0.4 mm (to the outer wall's centre), then 0.2 mm more (to the outline).
    EXPECT_EQ(skinReference(0, 2, 400, 400).wall, 2);
    EXPECT_EQ(skinReference(389, 2, 400, 400).wall, 2);
    // Within 10 µm of a wall's centre it ends there, nothing left over (CuraEngine 4.13's snap).
    for (coord_um near : {390, 410}) {
        const SkinReference snapped = skinReference(near, 2, 400, 400);
        EXPECT_EQ(snapped.wall, 1) << near;
        EXPECT_EQ(snapped.leftover_preshrink_um, 0) << near;
    }
    const SkinReference half = skinReference(500, 2, 400, 400);
    EXPECT_EQ(half.wall, 1);
    EXPECT_EQ(half.leftover_preshrink_um, 100);
    const SkinReference one = skinReference(1'000, 2, 400, 400);
    EXPECT_EQ(one.wall, 0);
    EXPECT_EQ(one.leftover_preshrink_um, 400);
    // Three walls (0.4, 0.5, 0.5 mm): 0.5 mm back to the second, 0.45 mm more to the outer one.
    const SkinReference three = skinReference(1'000, 3, 400, 500);
    EXPECT_EQ(three.wall, 1);
    EXPECT_EQ(three.leftover_preshrink_um, 50);
}

TEST(Skin, RoofingIsTheSkinWithAirAbove) {
    const std::vector<Paths> areas{sq(0, 20'000), sq(0, 20'000), sq(0, 20'000), sq(0, 10'000)};
    SkinParams p = layersOnly(2, 0);
    p.roofing_layers = 1;
    const std::vector<SkinAreas> s = skins(areas, p);
    EXPECT_EQ(areaUm2(s[2].roofing), 400e6 - 100e6);  // nothing above the L-shaped part
    EXPECT_EQ(areaUm2(s[2].skin), 400e6);             // the skin holds its roofing
    EXPECT_EQ(areaUm2(s[3].roofing), 100e6);
}

TEST(Skin, RoofingComparesWithItsOwnReferenceAndAtMostTopLayers) {
    // The outline reference says layer 1 is covered, the roofing reference (a wall's centre region,
    // smaller above) leaves a 1 mm band of layer 1 uncovered: roofing follows the roofing reference.
    const std::vector<Paths> outlines{sq(0, 20'000), sq(0, 20'000)};
    const std::vector<Paths> walls{sq(0, 20'000), sq(1'000, 18'000)};
    SkinParams p = layersOnly(2, 0);
    p.roofing_layers = 1;
    const std::vector<SkinAreas> s = computeSkinAreas({&outlines, &outlines, &walls}, outlines, p, 1);
    EXPECT_EQ(areaUm2(s[0].roofing), 400e6 - 18'000.0 * 18'000.0);
    EXPECT_EQ(areaUm2(s[0].skin), 400e6);
    // roofing_layer_count above top_layers counts as top_layers.
    const std::vector<Paths> stack{sq(0, 20'000), sq(0, 20'000), sq(0, 20'000), sq(0, 20'000)};
    SkinParams capped = layersOnly(1, 0);
    capped.roofing_layers = 3;
    EXPECT_TRUE(skins(stack, capped)[1].roofing.empty());  // layer 2 covers it
    EXPECT_EQ(areaUm2(skins(stack, capped)[3].roofing), 400e6);
}

TEST(Skin, OuterSurfacesHaveAirDirectlyAboveOrBelow) {
    // Four layers: a 20 mm square, then a 10 mm one on layers 2 and 3; all skin (2 top, 2 bottom).
    const std::vector<Paths> areas{sq(0, 20'000), sq(0, 20'000), sq(0, 10'000), sq(0, 10'000)};
    SkinParams p = layersOnly(2, 2);
    p.outer_surfaces = true;
    const std::vector<SkinAreas> s = skins(areas, p);
    EXPECT_EQ(areaUm2(s[0].outer_surfaces), 400e6);          // layer 0: air below
    EXPECT_EQ(areaUm2(s[1].outer_surfaces), 400e6 - 100e6);  // the L with nothing above
    EXPECT_EQ(areaUm2(s[2].outer_surfaces), 0.0);            // covered, and standing on layer 1
    EXPECT_EQ(areaUm2(s[3].outer_surfaces), 100e6);          // the top
    EXPECT_TRUE(skins(areas, layersOnly(2, 2))[3].outer_surfaces.empty());  // not asked for
}

TEST(Skin, InfillLosesWhatIsNarrowerThanItsLine) {
    // Inside the walls: a 10 mm square with a 0.3 mm wide, 5 mm long tongue; no skin.
    const Paths inner{{{0, 0},
                       {10'000, 0},
                       {10'000, 4'850},
                       {15'000, 4'850},
                       {15'000, 5'150},
                       {10'000, 5'150},
                       {10'000, 10'000},
                       {0, 10'000}}};
    const std::vector<Paths> areas(5, inner);
    SkinParams p = layersOnly(0, 0);
    EXPECT_EQ(areaUm2(skins(areas, p)[2].infill), areaUm2(inner));
    p.infill_opening_um = 400;  // infill_line_width: the tongue goes
    EXPECT_NEAR(areaUm2(skins(areas, p)[2].infill), 100e6, 1e3);
}

}  // namespace
}  // namespace mixengine
