// Overhanging walls (toolpaths/walls/OverhangWalls.h): the overhang mask and the wall vertices on it.
#include "toolpaths/walls/OverhangWalls.h"

#include <gtest/gtest.h>

#include "geometry/PointQueries.h"

namespace mixengine {
namespace {

Path box(coord_um x0, coord_um y0, coord_um x1, coord_um y1) {
    return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

OverhangWallParams params(double tan_angle, double speed_factor = 0.5) {
    OverhangWallParams p;
    p.enabled = true;
    p.tan_angle = tan_angle;
    p.outer_width_um = 400;
    p.speed_factor = speed_factor;
    return p;
}

TEST(OverhangWalls, TheMaskIsTheWallAreaBeyondTheLayerBelowGrownByTheAngle) {
    // A 20 mm part over a layer 10 mm wide: the right half overhangs. At 45° with 0.2 mm layers the
    // supported region reaches 10 + 200 − 200 µm past the layer below, the mask 10 µm further back.
    const Paths mask =
        overhangWallMask({box(0, 0, 20'000, 10'000)}, {box(0, 0, 10'000, 10'000)}, 200, params(1.0));
    ASSERT_FALSE(mask.empty());
    EXPECT_TRUE(insideArea(mask, {15'000, 5'000}, true));
    EXPECT_TRUE(insideArea(mask, {19'800, 200}, true));  // the wall's corner, half a line inside
    EXPECT_FALSE(insideArea(mask, {5'000, 5'000}, true));
    EXPECT_FALSE(insideArea(mask, {9'990, 5'000}, true));
    EXPECT_TRUE(insideArea(mask, {10'000, 5'000}, true));
    // A steeper angle lets the layer below carry further: at tan 10, 2 mm.
    const Paths steep =
        overhangWallMask({box(0, 0, 20'000, 10'000)}, {box(0, 0, 10'000, 10'000)}, 200, params(10));
    EXPECT_FALSE(insideArea(steep, {11'500, 5'000}, true));
    EXPECT_TRUE(insideArea(steep, {12'000, 5'000}, true));
    // Fully supported: no mask.
    EXPECT_TRUE(
        overhangWallMask({box(0, 0, 20'000, 10'000)}, {box(0, 0, 20'000, 10'000)}, 200, params(1.0)).empty());
}

TEST(OverhangWalls, WallVerticesOnTheMaskAreMarkedAndSmallFeaturesKeepTheirSpeed) {
    ExtrusionPath wall;
    wall.closed = true;
    wall.points = box(200, 200, 19'800, 9'800);
    ExtrusionPath supported = wall;
    supported.points = box(1'000, 1'000, 5'000, 5'000);
    std::vector<ExtrusionPath> walls{wall, supported};
    const Paths mask{box(10'000, 0, 20'000, 10'000)};
    markOverhangingWalls(walls, mask, params(1.0));
    EXPECT_EQ(walls[0].overhanging, (std::vector<std::uint8_t>{0, 1, 1, 0}));
    EXPECT_DOUBLE_EQ(walls[0].overhang_speed_factor, 0.5);
    EXPECT_TRUE(walls[1].overhanging.empty());
    EXPECT_DOUBLE_EQ(walls[1].overhang_speed_factor, 1.0);

    OverhangWallParams small = params(1.0);
    small.small_feature_max_um = 60'000;  // the 19.6 × 9.6 mm loop (58.4 mm) is a small feature
    std::vector<ExtrusionPath> one{wall};
    markOverhangingWalls(one, mask, small);
    EXPECT_EQ(one[0].overhanging.size(), 4U);
    EXPECT_DOUBLE_EQ(one[0].overhang_speed_factor, 1.0);
}

}  // namespace
}  // namespace mixengine
