// Small features (toolpaths/walls/SmallFeatures.h): short wall loops print slower.
#include "toolpaths/walls/SmallFeatures.h"

#include <gtest/gtest.h>

namespace mixengine {
namespace {

ExtrusionPath loopOfSide(coord_um side_um, double speed, bool closed = true) {
    ExtrusionPath path;
    path.points = {{0, 0}, {side_um, 0}, {side_um, side_um}, {0, side_um}};
    path.closed = closed;
    path.speed_mm_s = speed;
    return path;
}

TEST(SmallFeatures, LoopsShorterThanTheMaximumSlowDownButNotUnderTheMinimumSpeed) {
    SmallFeatureParams p;
    p.max_length_um = 4'000;
    p.speed_factor = 0.5;
    p.min_speed_mm_s = 10;
    // 3.6 mm round: slowed; 4 mm round: not (shorter only); an open line: not (a loop's length)
    std::vector<ExtrusionPath> walls = {loopOfSide(900, 40), loopOfSide(1'000, 40),
                                        loopOfSide(900, 40, false), loopOfSide(900, 15)};
    slowSmallFeatures(walls, p);
    EXPECT_DOUBLE_EQ(walls[0].speed_mm_s, 20);
    EXPECT_DOUBLE_EQ(walls[1].speed_mm_s, 40);
    EXPECT_DOUBLE_EQ(walls[2].speed_mm_s, 40);
    EXPECT_DOUBLE_EQ(walls[3].speed_mm_s, 10);  // 7.5 would be under cool_min_speed
    p.max_length_um = 0;                        // off
    std::vector<ExtrusionPath> off = {loopOfSide(900, 40)};
    slowSmallFeatures(off, p);
    EXPECT_DOUBLE_EQ(off[0].speed_mm_s, 40);
}

}  // namespace
}  // namespace mixengine
