#include "slicing/OutlineBuilder.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace mixengine {
namespace {

Path square(coord_um x0, coord_um y0, coord_um side) {
    return {{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}};
}

Path reversed(Path path) {
    std::reverse(path.begin(), path.end());
    return path;
}

/// A loop whose facets all agree with its direction as given.
StitchedPath loopAlongFacets(const Path& points) {
    return {points, 1000.0, 0.0};
}

/// A loop with no usable facet direction (half along, half against).
StitchedPath loopMixedFacets(const Path& points) {
    return {points, 500.0, 500.0};
}

std::vector<double> sortedAreas(const Paths& paths) {
    std::vector<double> areas;
    for (const Path& path : paths)
        areas.push_back(ClipperLib::Area(path));
    std::sort(areas.begin(), areas.end());
    return areas;
}

TEST(SlicingOutlines, CavityWoundInwardsIsAHole) {
    const std::vector<StitchedPath> loops{loopAlongFacets(square(0, 0, 100)),
                                          loopAlongFacets(reversed(square(25, 25, 50)))};
    EXPECT_EQ(sortedAreas(buildOutlines(loops, 0)), (std::vector<double>{-2500, 10000}));
}

TEST(SlicingOutlines, NestingDecidesWhenWindingIsUnusable) {
    // Both loops counter-clockwise with mixed facet votes: the inner one is still a hole.
    const std::vector<StitchedPath> loops{loopMixedFacets(square(0, 0, 100)),
                                          loopMixedFacets(square(25, 25, 50))};
    EXPECT_EQ(sortedAreas(buildOutlines(loops, 0)), (std::vector<double>{-2500, 10000}));
}

TEST(SlicingOutlines, AnInvertedOutermostLoopIsStillSolid) {
    const std::vector<StitchedPath> loops{loopAlongFacets(reversed(square(0, 0, 100)))};
    EXPECT_EQ(sortedAreas(buildOutlines(loops, 0)), (std::vector<double>{10000}));
}

TEST(SlicingOutlines, IslandInACavityIsSolid) {
    const std::vector<StitchedPath> loops{loopMixedFacets(square(0, 0, 100)),
                                          loopMixedFacets(square(20, 20, 60)),
                                          loopMixedFacets(square(40, 40, 20))};
    EXPECT_EQ(sortedAreas(buildOutlines(loops, 0)), (std::vector<double>{-3600, 400, 10000}));
}

TEST(SlicingOutlines, OutwardShellInsideASolidIsUnited) {
    const std::vector<StitchedPath> loops{loopAlongFacets(square(0, 0, 100)),
                                          loopAlongFacets(square(25, 25, 50))};
    EXPECT_EQ(sortedAreas(buildOutlines(loops, 0)), (std::vector<double>{10000}));
}

TEST(SlicingOutlines, OverlappingShellsAreUnited) {
    const std::vector<StitchedPath> loops{loopAlongFacets(square(0, 0, 100)),
                                          loopAlongFacets(square(50, 50, 100))};
    const Paths outlines = buildOutlines(loops, 0);
    ASSERT_EQ(outlines.size(), 1U);
    EXPECT_DOUBLE_EQ(ClipperLib::Area(outlines[0]), 17500);
    EXPECT_EQ(outlines[0].size(), 8U);
}

TEST(SlicingOutlines, DropsZeroAndTinyLoops) {
    const std::vector<StitchedPath> loops{loopAlongFacets({{0, 0}, {100, 0}}),            // a sliver
                                          loopAlongFacets({{0, 0}, {100, 0}, {200, 0}}),  // collinear
                                          loopAlongFacets(square(500, 500, 5)),           // 25 µm²
                                          loopAlongFacets(square(1000, 1000, 100))};
    EXPECT_EQ(sortedAreas(buildOutlines(loops, 30)), (std::vector<double>{10000}));
}

TEST(SlicingOutlines, WithoutUnionAllOverlappingShellsLeaveAHoleWhereTheyOverlap) {
    // meshfix_union_all off: two outward shells overlapping by 50 x 100 — even-odd, so the overlap is empty
    const std::vector<StitchedPath> loops{loopAlongFacets(square(0, 0, 100)),
                                          loopAlongFacets(square(50, 0, 100))};
    double united = 0, even_odd = 0;
    for (const Path& p : buildOutlines(loops, 0))
        united += ClipperLib::Area(p);
    for (const Path& p : evenOddOutlines(loops, 0))
        even_odd += ClipperLib::Area(p);
    EXPECT_DOUBLE_EQ(united, 15000);
    EXPECT_DOUBLE_EQ(even_odd, 10000);
    EXPECT_EQ(evenOddOutlines(loops, 0).size(), 2U);  // the two 50 x 100 strips left
}

TEST(SlicingOutlines, EvenOddDropsTinyLoopsAndIgnoresWinding) {
    const std::vector<StitchedPath> loops{loopMixedFacets(reversed(square(0, 0, 100))),
                                          loopMixedFacets(square(25, 25, 50)),
                                          loopMixedFacets(square(500, 0, 1))};
    EXPECT_EQ(sortedAreas(evenOddOutlines(loops, 10)), (std::vector<double>{-2500, 10000}));
}

}  // namespace
}  // namespace mixengine
