// The cross fractal (toolpaths/infill/cross/): its square, its curve through the triangles, the
// cross_3d variant with its pockets, an image's density and the pattern cut to an area.
#include "toolpaths/infill/cross/CrossFill.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ToolpathTestSupport.h"
#include "geometry/PolygonOps.h"
#include "toolpaths/infill/InfillPatterns.h"
#include "toolpaths/infill/cross/CrossCurve.h"
#include "toolpaths/infill/cross/DensityImage.h"
#include "toolpaths/infill/cross/SierpinskiSequence.h"

namespace mixengine {
namespace {

constexpr coord_um kDistance = 2'000;  ///< line distance
constexpr coord_um kWidth = 400;       ///< line width

/// A 64 mm model: the square is 64 mm (2 mm · 2^5), depth 10, and its leaves have legs 2√2 mm.
const Box2 kModel{-32'000, -32'000, 32'000, 32'000};

bool inside(const Point2& p, const Box2& box) {
    return p.X >= box.left && p.X <= box.right && p.Y >= box.top && p.Y <= box.bottom;
}

TEST(CrossFill, SquareDoublesTheLineDistanceUntilItCoversTheModel) {
    // 100 × 50 mm: 2 mm · 2^6 = 128 mm; 128 · √2/2 = 90.5 mm would not cover 100 mm
    const CrossSquare wide = crossSquare({0, 0, 100'000, 50'000}, kDistance);
    EXPECT_EQ(wide.depth, 12);
    EXPECT_EQ(wide.square.right - wide.square.left, 128'000);
    EXPECT_EQ((wide.square.left + wide.square.right) / 2, 50'000);
    EXPECT_EQ((wide.square.top + wide.square.bottom) / 2, 25'000);
    // 80 mm: 128 mm · √2/2 = 90.5 mm still covers it, one level less
    const CrossSquare smaller = crossSquare({0, 0, 80'000, 80'000}, kDistance);
    EXPECT_EQ(smaller.depth, 11);
    EXPECT_NEAR(double(smaller.square.right - smaller.square.left), 128'000 / std::numbers::sqrt2, 2.0);
}

TEST(CrossFill, UniformDensitySubdividesEveryTriangleToTheDeepestLevel) {
    // Every leaf (area d²) asks for d of curve and realizes at most d, so all are crossed — but for
    // one triangle, as in CuraEngine: the square's two halves are both entered by AC, so the last
    // triangle of the first half (crossed from AC to AB) waits for a partner across AB that never
    // comes and stays one level up.
    SierpinskiTree tree({-32'000, -32'000, 32'000, 32'000}, 10, kWidth,
                        [](const Box2&) { return float(kWidth) / float(kDistance); });
    const std::vector<int> sequence = crossSequence(tree);
    ASSERT_EQ(sequence.size(), 1023U);
    for (std::size_t i = 0; i < sequence.size(); ++i)
        EXPECT_EQ(tree.node(sequence[i]).depth, i == 510 ? 9 : 10) << i;
}

TEST(CrossFill, CurveIsClosedContinuousSimpleAndInsideTheSquare) {
    const Path curve = CrossFill(kModel, kDistance, kWidth).curve(false, 0, kWidth, 0);
    ASSERT_EQ(curve.size(), 1023U);
    // Consecutive vertices are midpoints of two sides of one triangle: half a leaf's hypotenuse
    // (2 mm) or leg (√2 mm) apart, or, at the one coarser triangle, half of its hypotenuse (2√2 mm);
    // also from the last vertex back to the first.
    const double sqrt2 = std::numbers::sqrt2;
    for (std::size_t i = 0; i < curve.size(); ++i) {
        const double step = distanceUm(curve[i], curve[(i + 1) % curve.size()]);
        const bool expected = std::abs(step - 1'000 * sqrt2) < 3 || std::abs(step - 2'000) < 3 ||
                              std::abs(step - 2'000 * sqrt2) < 3;
        EXPECT_TRUE(expected) << i << ": " << step;
        EXPECT_TRUE(inside(curve[i], kModel));
    }
    // Simple: the union of the loop with itself covers just its own area.
    const double own = std::abs(areaUm2({curve}));
    EXPECT_GT(own, 0.3 * 64'000.0 * 64'000.0);
    EXPECT_NEAR(areaUm2(unionOf({curve})), own, own * 1e-6);
}

TEST(CrossFill, LengthPerAreaFollowsTheLineDistance) {
    // Between √2/2 and 1 of the lines' length at the same distance (area / d): each leaf's part of the
    // curve is half a leg or half the hypotenuse.
    const double length = lengthUm(CrossFill(kModel, kDistance, kWidth).curve(false, 0, kWidth, 0), true);
    const double lines = 64'000.0 * 64'000.0 / double(kDistance);
    EXPECT_GT(length, lines * std::numbers::sqrt2 / 2 - 1);
    EXPECT_LT(length, lines + 1);
    // Twice the distance: the model fits a square one level shallower: half the curve (± rounding).
    const double sparse = lengthUm(CrossFill(kModel, 2 * kDistance, kWidth).curve(false, 0, kWidth, 0), true);
    EXPECT_NEAR(sparse / length, 0.5, 0.01);
}

TEST(CrossFill, SameCurveEveryTime) {
    const Box2 model{3'000, -7'000, 75'000, 41'000};
    EXPECT_EQ(CrossFill(model, 3'000, kWidth).curve(false, 0, kWidth, 0),
              CrossFill(model, 3'000, kWidth).curve(false, 0, kWidth, 0));
    EXPECT_EQ(CrossFill(model, 3'000, kWidth).curve(true, 1'200, kWidth, 3'000),
              CrossFill(model, 3'000, kWidth).curve(true, 1'200, kWidth, 3'000));
}

TEST(CrossFill, Cross3dSlidesAlongTheEdgesWithHeight) {
    const CrossFill fill(kModel, kDistance, kWidth);
    const Path low = fill.curve(true, 200, kWidth, 0);
    const Path high = fill.curve(true, 1'400, kWidth, 0);
    ASSERT_EQ(low.size(), 1024U);  // one vertex per triangle and the last one's exit
    ASSERT_EQ(high.size(), low.size());
    EXPECT_NE(low, high);
    // Period 2 · 2√2 mm: z and 2·period − z give the same curve.
    const coord_um period = static_cast<coord_um>(2'000 * std::numbers::sqrt2);
    const Path mirrored = fill.curve(true, 2 * period - 200, kWidth, 0);
    std::size_t close = 0;
    for (std::size_t i = 0; i < low.size(); ++i)
        close += distanceUm(low[i], mirrored[i]) < 10 ? 1 : 0;
    EXPECT_GT(close, low.size() * 9 / 10);
    // The vertices keep half a line width from the triangles' corners: none on the square's corners.
    for (const Point2& p : low)
        EXPECT_TRUE(inside(p, kModel));
}

TEST(CrossFill, PocketsCutTheRightAngledCorners) {
    const CrossFill fill(kModel, kDistance, kWidth);
    const Path plain = fill.curve(true, 600, kWidth, 0);
    const Path pocketed = fill.curve(true, 600, kWidth, 2'000);
    EXPECT_GT(pocketed.size(), plain.size());
    EXPECT_LT(lengthUm(pocketed, true), lengthUm(plain, true));  // a corner cut is shorter
    EXPECT_EQ(fill.curve(true, 600, kWidth, 10), plain);         // 10 µm and less: no pockets
}

TEST(CrossFill, ImageDensityFollowsTheGreyLevels) {
    // Left half dark grey (density 0.2 = w/d, the deepest level), right half nearly white (0.02).
    DecodedImage image{2, 1, 1, {204, 250}};
    const DensityAt density = imageDensity(image, kModel);
    EXPECT_NEAR(density({-30'000, -5'000, -20'000, 5'000}), 0.2, 0.001);
    EXPECT_NEAR(density({20'000, -5'000, 30'000, 5'000}), 1.0 - 250.0 / 255, 0.001);
    const Path curve = CrossFill(kModel, kDistance, kWidth, density).curve(false, 0, kWidth, 0);
    const Paths left{test::rect(-32'000, -32'000, -2'000, 32'000)},
        right{test::rect(2'000, -32'000, 32'000, 32'000)};
    Path closed = curve;
    closed.push_back(curve.front());
    double left_length = 0, right_length = 0;
    for (const Path& piece : clipLines({closed}, left))
        left_length += lengthUm(piece, false);
    for (const Path& piece : clipLines({closed}, right))
        right_length += lengthUm(piece, false);
    EXPECT_GT(left_length, 3 * right_length);
    // The dark half is filled about as densely as a uniform fill.
    EXPECT_GT(left_length, 0.6 * 30'000.0 * 64'000.0 / double(kDistance));
}

TEST(CrossFill, PatternCutToTheArea) {
    const CrossFill fill(kModel, kDistance, kWidth);
    InfillParams p;
    p.pattern = InfillPattern::Cross;
    p.line_distance_um = kDistance;
    p.line_width_um = kWidth;
    p.cross = &fill;
    const Paths area{test::square(-20'000, -20'000, 30'000)};
    p.connect_lines = true;  // zig_zaggify: loops inside the area less half a line
    const std::vector<ExtrusionPath> loops = generateInfill(area, p);
    ASSERT_FALSE(loops.empty());
    const Box2 inner{-20'000 + kWidth / 2, -20'000 + kWidth / 2, 10'000 - kWidth / 2, 10'000 - kWidth / 2};
    for (const ExtrusionPath& loop : loops) {
        EXPECT_TRUE(loop.closed);
        for (const Point2& point : loop.points)
            EXPECT_TRUE(inside(point, inner));
    }
    p.connect_lines = false;  // else every piece of the curve a line of its own
    const std::vector<ExtrusionPath> lines = generateInfill(area, p);
    for (const ExtrusionPath& line : lines) {
        EXPECT_FALSE(line.closed);
        EXPECT_EQ(line.points.size(), 2U);
    }
    // The curve's share of the area: between √2/2 and 1 of lines at the distance.
    const double per_area = test::totalLength(lines) / (30'000.0 * 30'000.0) * double(kDistance);
    EXPECT_GT(per_area, 0.65);
    EXPECT_LT(per_area, 1.05);
    EXPECT_GT(test::totalLength(loops), test::totalLength(lines));  // the joins along the edge
}

}  // namespace
}  // namespace mixengine
