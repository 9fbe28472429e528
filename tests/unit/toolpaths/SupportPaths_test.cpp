// The lines of one support layer (toolpaths/support/SupportPaths.h) with an infill arrangement: gradual
// support densities and support layers combined into thicker ones.
#include "toolpaths/support/SupportPaths.h"

#include "geometry/PolygonOps.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <utility>

namespace mixengine {
namespace {

Paths square(coord_um x0, coord_um y0, coord_um size) {
    return {{{x0, y0}, {x0 + size, y0}, {x0 + size, y0 + size}, {x0, y0 + size}}};
}

SupportLayerFills lines2mm() {
    SupportLayerFills fills;
    fills.body.pattern = InfillPattern::Lines;
    fills.body.line_distance_um = 2'000;
    fills.body.style = {400, 50, 1.0, 0};
    return fills;
}

double flowTimesLength(const std::vector<ExtrusionPath>& paths) {
    double sum = 0;
    for (const ExtrusionPath& p : paths)
        sum += p.flow * lengthUm(p.points, p.closed);
    return sum;
}

TEST(SupportPaths, WithoutArrangementTheWholeBodyAtItsLineDistance) {
    SupportLayerAreas areas;
    areas.support = square(0, 0, 20'000);
    const std::vector<ExtrusionPath> plain = supportLayerPaths(areas, lines2mm(), 200);
    ASSERT_FALSE(plain.empty());
    LayerInfill one;  // one density, one layer thick: the same lines
    one.by_density = {{areas.support}};
    EXPECT_NEAR(flowTimesLength(supportLayerPaths(areas, lines2mm(), 200, &one)), flowTimesLength(plain),
                1.0);
}

TEST(SupportPaths, GradualDensitiesAndThickerLayers) {
    SupportLayerAreas areas;
    areas.support = square(0, 0, 20'000);
    const double full = flowTimesLength(supportLayerPaths(areas, lines2mm(), 200));
    // Two densities: the whole square at the sparser spacing (4 mm: 5 lines of 20 mm), its left half
    // also at the denser one's (4 mm apart, shifted by 2 mm: 2 or 3 more lines of 10 mm between them).
    LayerInfill gradual;
    gradual.by_density = {{square(0, 0, 10'000)}, {areas.support}};
    const double graded = flowTimesLength(supportLayerPaths(areas, lines2mm(), 200, &gradual));
    EXPECT_GE(graded, 0.6 * full);
    EXPECT_LE(graded, 0.65 * full + 1.0);
    // The whole square two layers thick: the same lines with twice the flow, nothing single.
    LayerInfill thick;
    thick.by_density = {{Paths{}, areas.support}};
    const std::vector<ExtrusionPath> doubled = supportLayerPaths(areas, lines2mm(), 200, &thick);
    ASSERT_FALSE(doubled.empty());
    for (const ExtrusionPath& p : doubled)
        EXPECT_DOUBLE_EQ(p.flow, 2.0);
    EXPECT_NEAR(flowTimesLength(doubled), 2.0 * full, 0.02 * full);
}

/// The smallest and largest Y of every point of `paths`.
std::pair<coord_um, coord_um> yRange(const std::vector<ExtrusionPath>& paths) {
    coord_um lo = std::numeric_limits<coord_um>::max();
    coord_um hi = std::numeric_limits<coord_um>::min();
    for (const ExtrusionPath& p : paths) {
        for (const Point2& q : p.points) {
            lo = std::min(lo, q.Y);
            hi = std::max(hi, q.Y);
        }
    }
    return {lo, hi};
}

TEST(SupportPaths, ThickerZigzagKeepsAsFarFromTheEdgeAsAWiderLine) {
    // As CuraEngine 4.13: support infill printed two layers thick is laid out for a line twice as
    // wide (its zigzag runs 2 × 400 / 2 = 400 µm inside the area, not 200 µm), printed 400 µm wide at
    // twice the flow.
    SupportLayerAreas areas;
    areas.support = square(0, 0, 20'000);
    SupportLayerFills fills = lines2mm();
    fills.body.pattern = InfillPattern::ZigZag;
    LayerInfill single;
    single.by_density = {{areas.support}};
    EXPECT_EQ(yRange(supportLayerPaths(areas, fills, 200, &single)), std::make_pair(200LL, 19'800LL));
    LayerInfill thick;
    thick.by_density = {{Paths{}, areas.support}};
    const std::vector<ExtrusionPath> doubled = supportLayerPaths(areas, fills, 200, &thick);
    ASSERT_FALSE(doubled.empty());
    EXPECT_EQ(yRange(doubled), std::make_pair(400LL, 19'600LL));
    for (const ExtrusionPath& p : doubled) {
        EXPECT_EQ(p.width_um, 400);
        EXPECT_DOUBLE_EQ(p.flow, 2.0);
    }
}

TEST(SupportPaths, InfillOverlapsTheWallsBySupportOverlap) {
    // One wall (its centre 200 µm inside, its inner edge at 400 µm); the zigzag's border runs half a
    // line inside that edge (600 µm), less the 120 µm overlap CuraEngine gives it when there are walls.
    SupportLayerAreas areas;
    areas.support = square(0, 0, 20'000);
    SupportLayerFills fills = lines2mm();
    fills.body.pattern = InfillPattern::ZigZag;
    fills.body.wall_count = 1;
    std::vector<ExtrusionPath> paths = supportLayerPaths(areas, fills, 200);
    ASSERT_GE(paths.size(), 2U);
    paths.erase(paths.begin());  // the wall
    EXPECT_EQ(yRange(paths), std::make_pair(600LL, 19'400LL));
    fills.body.overlap_um = 120;
    paths = supportLayerPaths(areas, fills, 200);
    paths.erase(paths.begin());
    EXPECT_EQ(yRange(paths), std::make_pair(480LL, 19'520LL));
}

}  // namespace
}  // namespace mixengine
