// The lines of one support layer (toolpaths/SupportPaths.h) with an infill arrangement: gradual
// support densities and support layers combined into thicker ones.
#include "toolpaths/SupportPaths.h"

#include "toolpaths/PolygonOps.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace mixengine
