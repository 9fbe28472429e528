// Overlap compensation switched by the settings on a mesh's walls (toolpaths/MeshToolpaths.h with
// toolpaths/walls/WallOverlap.h): a 0.6 mm fin's outer wall and a 1.4 mm rib's inner wall run back along
// themselves 0.2 mm away with 0.4 mm lines.
#include <gtest/gtest.h>

#include <algorithm>

#include "ToolpathTestSupport.h"
#include "toolpaths/MeshToolpaths.h"

namespace mixengine {
namespace {

using test::rect;

/// The walls of one layer of an 8 mm long part `width_um` wide, with the given switches.
MeshLayerGroups wallsOf(coord_um width_um, const char* outer, const char* inner) {
    test::Stack s = test::prismStack(6);
    test::fill(s, 0, 6, {rect(10'000, 10'000, 18'000, 10'000 + width_um)});
    const ResolvedMachine m = test::fdmMachine({{"wall_line_count", "2"},
                                                {"travel_compensate_overlapping_walls_0_enabled", outer},
                                                {"travel_compensate_overlapping_walls_x_enabled", inner}},
                                               {{1, {}}});
    return generateMeshToolpaths(s.layers, m.global, 1)[3];
}

/// The smallest per-point flow of the paths (1 when none carries per-point flows).
double leastFlow(const std::vector<ExtrusionPath>& paths) {
    double least = 1.0;
    for (const ExtrusionPath& p : paths) {
        for (std::size_t k = 0; k < p.flows.size(); ++k)
            least = std::min(least, p.flows[k]);
    }
    return least;
}

TEST(WallOverlapMesh, TheFinsOuterWallPrintsItsWayBackAtHalfFlowWhenSwitchedOn) {
    const MeshLayerGroups on = wallsOf(600, "True", "False");
    ASSERT_EQ(on.outer_walls.size(), 1U);
    EXPECT_DOUBLE_EQ(leastFlow(on.outer_walls), 0.5);
    const MeshLayerGroups off = wallsOf(600, "False", "True");
    ASSERT_EQ(off.outer_walls.size(), 1U);
    EXPECT_TRUE(off.outer_walls[0].flows.empty());
}

TEST(WallOverlapMesh, TheRibsInnerWallIsCompensatedAtOneMicronLessThanItsWidth) {
    // The inner wall's loop is 1.4 − 2 × 0.6 = 0.2 mm wide: the way back overlaps by 399 − 200 of
    // 399 µm; the outer walls, 1 mm apart, keep their flow.
    const MeshLayerGroups on = wallsOf(1'400, "True", "True");
    ASSERT_EQ(on.inner_walls.size(), 1U);
    EXPECT_NEAR(leastFlow(on.inner_walls), 200.0 / 399.0, 1e-9);
    EXPECT_TRUE(on.outer_walls[0].flows.empty());
    const MeshLayerGroups off = wallsOf(1'400, "True", "False");
    EXPECT_TRUE(off.inner_walls[0].flows.empty());
}

}  // namespace
}  // namespace mixengine
