// Outline gaps (toolpaths/walls/OutlineGaps.h): what of the outline the outer wall leaves, and its lines.
#include "toolpaths/walls/OutlineGaps.h"

#include <gtest/gtest.h>

#include "ToolpathTestSupport.h"
#include "geometry/PolygonOps.h"

namespace mixengine {
namespace {

using test::square;

TEST(OutlineGaps, AWallThatReachesTheOutlineLeavesNone) {
    // A 10 mm square, its outer wall's centre region 0.2 mm inside: the wall covers it to the edge.
    const Paths outline{square(0, 0, 10'000)};
    EXPECT_TRUE(outlineGaps(outline, {square(200, 200, 9'600)}, 400, 0).empty());
}

TEST(OutlineGaps, APartWithoutWallIsAGapAsAWholeUnlessTiny) {
    // A 0.3 x 10 mm strip has no wall: all of it (3 mm², over 2 widths squared) is a gap; a
    // 0.3 x 1 mm one (0.3 mm²) is under 2 x 0.4² mm² and goes.
    const Path long_strip{{0, 0}, {300, 0}, {300, 10'000}, {0, 10'000}};
    const Paths gaps = outlineGaps({long_strip}, {}, 400, 0);
    ASSERT_EQ(gaps.size(), 1U);
    EXPECT_NEAR(areaUm2(gaps), 3e6, 1e3);
    const Path short_strip{{0, 0}, {300, 0}, {300, 1'000}, {0, 1'000}};
    EXPECT_TRUE(outlineGaps({short_strip}, {}, 400, 0).empty());
}

TEST(OutlineGaps, GapLinesAreOneWidthApartInTheStyle) {
    const Path strip{{0, 0}, {2'000, 0}, {2'000, 10'000}, {0, 10'000}};
    const FeatureStyle style{200, 25, 0.9, 1};
    const std::vector<ExtrusionPath> lines = outlineGapLines({strip}, 0, style);  // along y
    ASSERT_EQ(lines.size(), 10U);  // x = 200, 400, ... 1800 and 0 or 2000 on the edge
    for (const ExtrusionPath& line : lines) {
        EXPECT_EQ(line.feature, Feature::Skin);
        EXPECT_EQ(line.width_um, 200);
        EXPECT_EQ(line.extruder, 1);
        EXPECT_FALSE(line.closed);
    }
    EXPECT_TRUE(outlineGapLines({}, 0, style).empty());
}

}  // namespace
}  // namespace mixengine
