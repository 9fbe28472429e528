// Cubic subdivision infill (toolpaths/infill/SubdivCubes.h): an octree fine at the walls, coarse inside.
#include "toolpaths/infill/SubdivCubes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "ToolpathTestSupport.h"
#include "geometry/PolygonOps.h"

namespace mixengine {
namespace {

double lengthOf(const Paths& lines) {
    double total = 0;
    for (const Path& l : lines)
        total += lengthUm(l, false);
    return total;
}

SubdivCubeParams params(coord_um distance) {
    SubdivCubeParams p;
    p.line_distance_um = distance;
    p.origin_um = {50'000, 50'000};
    p.layer_height_um = 200;
    return p;
}

/// A 100 mm box, 60 mm tall, at 0.2 mm layers.
std::vector<Paths> box() {
    return std::vector<Paths>(300, Paths{test::square(0, 0, 100'000)});
}

TEST(SubdivCubes, DenserAlongTheWallsThanInside) {
    const SubdivCubes cubes(params(5'000), box());
    EXPECT_GT(cubes.cubeCount(), 100U);
    const Paths lines = cubes.linesAt(30'000);
    const Paths band = differenceOf({test::square(0, 0, 100'000)}, {test::square(10'000, 10'000, 80'000)});
    const Paths middle{test::square(35'000, 35'000, 30'000)};
    const double band_density = lengthOf(clipLines(lines, band)) / areaUm2(band);
    const double middle_density = lengthOf(clipLines(lines, middle)) / areaUm2(middle);
    EXPECT_GT(band_density, 1.5 * middle_density);
}

TEST(SubdivCubes, ThreeDirectionsAtTheAngle) {
    SubdivCubeParams p = params(5'000);
    p.angle_degrees = 30;
    const Paths lines = SubdivCubes(p, box()).linesAt(20'000);
    ASSERT_FALSE(lines.empty());
    std::set<long> directions;
    for (const Path& l : lines) {
        const double a =
            std::atan2(double(l[1].Y - l[0].Y), double(l[1].X - l[0].X)) * 180 / std::numbers::pi;
        directions.insert(std::lround(std::fmod(a + 360.0, 180.0)) % 180);
    }
    EXPECT_EQ(directions.size(), 3U);
}

TEST(SubdivCubes, NoModelNoSubdivision) {
    const SubdivCubes cubes(params(5'000), {});
    EXPECT_EQ(cubes.cubeCount(), 1U);
    EXPECT_TRUE(SubdivCubes(params(0), box()).linesAt(1'000).empty());
}

}  // namespace
}  // namespace mixengine
