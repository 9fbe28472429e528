#include "slicing/FacetPlane.h"

#include <gtest/gtest.h>

#include <array>
#include <set>

#include "common/Error.h"

namespace mixengine {
namespace {

struct SignCase {
    std::array<int, 3> signs;
    int expected_case;
};

// All 27 sign patterns of (V1, V2, V3), written out by hand from seed 003's table.
const std::array<SignCase, 27> kAllPatterns{{
    {{-1, -1, -1}, 14}, {{1, 1, 1}, 14},                                      // no contact
    {{0, 0, 0}, 13},                                                          // facet in plane
    {{0, 0, 1}, 7},     {{0, 0, -1}, 7},  {{1, 0, 0}, 8},  {{-1, 0, 0}, 8},   // two vertices
    {{0, 1, 0}, 9},     {{0, -1, 0}, 9},                                      //
    {{0, 1, 1}, 1},     {{0, -1, -1}, 1}, {{1, 0, 1}, 2},  {{-1, 0, -1}, 2},  // one vertex, touch
    {{1, 1, 0}, 3},     {{-1, -1, 0}, 3},                                     //
    {{0, 1, -1}, 4},    {{0, -1, 1}, 4},  {{1, 0, -1}, 5}, {{-1, 0, 1}, 5},   // vertex and edge
    {{1, -1, 0}, 6},    {{-1, 1, 0}, 6},                                      //
    {{-1, 1, -1}, 10},  {{1, -1, 1}, 10},                                     // V2 alone: L1, L2
    {{-1, -1, 1}, 11},  {{1, 1, -1}, 11},                                     // V3 alone: L2, L3
    {{1, -1, -1}, 12},  {{-1, 1, 1}, 12},                                     // V1 alone: L3, L1
}};

TEST(FacetPlaneCases, AllTwentySevenSignPatternsMapToTheirCase) {
    std::set<std::array<int, 3>> seen;
    std::set<int> cases;
    for (const SignCase& c : kAllPatterns) {
        EXPECT_TRUE(seen.insert(c.signs).second) << "pattern listed twice";
        const FacetPlaneCase got = classifyFacetPlane(c.signs[0], c.signs[1], c.signs[2]);
        EXPECT_EQ(static_cast<int>(got), c.expected_case)
            << "signs " << c.signs[0] << ' ' << c.signs[1] << ' ' << c.signs[2];
        cases.insert(static_cast<int>(got));
    }
    EXPECT_EQ(seen.size(), 27U);
    EXPECT_EQ(cases.size(), 14U);  // every case is reached
}

/// The seed's 14 conditions, evaluated literally with P(Vi) = sign.
std::set<int> seedConditionsMet(int p1, int p2, int p3) {
    const std::array<bool, 15> met{false,
                                   p1 == 0 && p2 * p3 > 0,
                                   p2 == 0 && p3 * p1 > 0,
                                   p3 == 0 && p1 * p2 > 0,
                                   p1 == 0 && p2 * p3 < 0,
                                   p2 == 0 && p3 * p1 < 0,
                                   p3 == 0 && p1 * p2 < 0,
                                   p1 == 0 && p2 == 0,
                                   p2 == 0 && p3 == 0,
                                   p3 == 0 && p1 == 0,
                                   p1 * p2 < 0 && p2 * p3 < 0,
                                   p2 * p3 < 0 && p3 * p1 < 0,
                                   p3 * p1 < 0 && p1 * p2 < 0,
                                   p1 == 0 && p2 == 0 && p3 == 0,
                                   (p1 > 0 && p2 > 0 && p3 > 0) || (p1 < 0 && p2 < 0 && p3 < 0)};
    std::set<int> out;
    for (int i = 1; i <= 14; ++i) {
        if (met[i])
            out.insert(i);
    }
    return out;
}

TEST(FacetPlaneCases, AgreesWithTheSeedConditionsAndTestsCase13First) {
    for (int p1 = -1; p1 <= 1; ++p1) {
        for (int p2 = -1; p2 <= 1; ++p2) {
            for (int p3 = -1; p3 <= 1; ++p3) {
                const std::set<int> met = seedConditionsMet(p1, p2, p3);
                const int got = static_cast<int>(classifyFacetPlane(p1, p2, p3));
                ASSERT_FALSE(met.empty()) << "a gap in the seed's table";
                EXPECT_TRUE(met.count(got)) << p1 << p2 << p3;
                if (p1 == 0 && p2 == 0 && p3 == 0) {
                    EXPECT_EQ(met, (std::set<int>{7, 8, 9, 13}));
                    EXPECT_EQ(got, 13);
                } else {
                    EXPECT_EQ(met.size(), 1U) << p1 << p2 << p3;
                }
            }
        }
    }
}

TEST(FacetPlaneCases, RejectsSignsOutOfRange) {
    EXPECT_THROW(classifyFacetPlane(2, 0, 0), InternalError);
    EXPECT_EQ(planeSign(5, 3), 1);
    EXPECT_EQ(planeSign(3, 3), 0);
    EXPECT_EQ(planeSign(-7, 3), -1);
}

// A facet of the +x wall of a box, wound counter-clockwise seen from outside (normal +x).
const Point3 kWallLow0{1000, 0, 0};
const Point3 kWallLow1{1000, 1000, 0};
const Point3 kWallHigh{1000, 0, 1000};

TEST(FacetPlaneSegment, GeneralCaseRunsWithTheSolidOnItsLeft) {
    const auto segment = cutFacet(kWallLow0, kWallLow1, kWallHigh, 500, OnPlaneRule::CountAsAbove);
    ASSERT_TRUE(segment);
    // Solid at x < 1000 is on the left when walking towards +y.
    EXPECT_EQ(segment->from, (Point2{1000, 0}));
    EXPECT_EQ(segment->to, (Point2{1000, 500}));
    const auto flipped = cutFacet(kWallLow0, kWallHigh, kWallLow1, 500, OnPlaneRule::CountAsAbove);
    ASSERT_TRUE(flipped);
    EXPECT_EQ(flipped->from, segment->to);
    EXPECT_EQ(flipped->to, segment->from);
}

TEST(FacetPlaneSegment, OddVertexBelowKeepsTheDirection) {
    // The same wall, other triangle: one vertex below, two above.
    const Point3 a{1000, 1000, 1000}, b{1000, 0, 1000}, c{1000, 1000, 0};
    const auto segment = cutFacet(a, b, c, 250, OnPlaneRule::CountAsAbove);
    ASSERT_TRUE(segment);
    EXPECT_LT(segment->from.Y, segment->to.Y);
}

TEST(FacetPlaneSegment, SingleVertexTouchGivesNoSegment) {  // cases 1–3, Rule ①
    // The highest vertex on the plane, the others below.
    EXPECT_FALSE(cutFacet(kWallLow0, kWallLow1, kWallHigh, 1000, OnPlaneRule::CountAsAbove));
    EXPECT_FALSE(cutFacet(kWallLow0, kWallLow1, kWallHigh, 1000, OnPlaneRule::CountAsBelow));
    // The lowest vertex on the plane, the others above.
    const Point3 a{0, 0, 0}, b{1000, 0, 1000}, c{0, 1000, 1000};
    EXPECT_FALSE(cutFacet(a, b, c, 0, OnPlaneRule::CountAsAbove));
    EXPECT_FALSE(cutFacet(a, b, c, 0, OnPlaneRule::CountAsBelow));
}

TEST(FacetPlaneSegment, VertexAndOppositeEdgeGivesTheSegmentFromTheVertex) {  // cases 4–6
    const Point3 v1{0, 0, 500}, v2{1000, 0, 0}, v3{1000, 1000, 1000};
    ASSERT_EQ(classifyFacetPlane(planeSign(v1.z, 500), planeSign(v2.z, 500), planeSign(v3.z, 500)),
              FacetPlaneCase::VertexV1EdgeL2);
    for (OnPlaneRule rule : {OnPlaneRule::CountAsAbove, OnPlaneRule::CountAsBelow}) {
        const auto segment = cutFacet(v1, v2, v3, 500, rule);
        ASSERT_TRUE(segment);
        const std::set<std::pair<coord_um, coord_um>> ends{{segment->from.X, segment->from.Y},
                                                           {segment->to.X, segment->to.Y}};
        EXPECT_EQ(ends, (std::set<std::pair<coord_um, coord_um>>{{0, 0}, {1000, 500}}));
    }
}

TEST(FacetPlaneSegment, EdgeInPlaneCountsOnlyForTheFacetBelow) {  // cases 7–9, Rule ②
    const Point3 e1{0, 0, 500}, e2{1000, 0, 500};
    const Point3 below{500, 500, 0}, above{500, 500, 1000};
    const auto from_below = cutFacet(e1, e2, below, 500, OnPlaneRule::CountAsAbove);
    ASSERT_TRUE(from_below);
    EXPECT_FALSE(cutFacet(e2, e1, above, 500, OnPlaneRule::CountAsAbove));
    // The mirrored rule keeps the other facet.
    EXPECT_FALSE(cutFacet(e1, e2, below, 500, OnPlaneRule::CountAsBelow));
    EXPECT_TRUE(cutFacet(e2, e1, above, 500, OnPlaneRule::CountAsBelow));
}

TEST(FacetPlaneSegment, FacetInThePlaneGivesNoSegment) {  // case 13
    const Point3 a{0, 0, 500}, b{1000, 0, 500}, c{0, 1000, 500};
    EXPECT_FALSE(cutFacet(a, b, c, 500, OnPlaneRule::CountAsAbove));
    EXPECT_FALSE(cutFacet(a, b, c, 500, OnPlaneRule::CountAsBelow));
}

TEST(FacetPlaneSegment, NoContactGivesNoSegment) {  // case 14
    EXPECT_FALSE(cutFacet(kWallLow0, kWallLow1, kWallHigh, 1001, OnPlaneRule::CountAsAbove));
    EXPECT_FALSE(cutFacet(kWallLow0, kWallLow1, kWallHigh, -1, OnPlaneRule::CountAsAbove));
}

TEST(FacetPlaneInterpolation, RoundsToTheNearestMicronExactly) {
    const Point3 low{0, 0, 0};
    EXPECT_EQ(interpolateEdge(low, {1, 2, 3}, 1), (Point2{0, 1}));        // 1/3, 2/3
    EXPECT_EQ(interpolateEdge(low, {1, 2, 3}, 2), (Point2{1, 1}));        // 2/3, 4/3
    EXPECT_EQ(interpolateEdge(low, {-1, 1, 2}, 1), (Point2{-1, 1}));      // halves away from zero
    EXPECT_EQ(interpolateEdge(low, {10, 20, 30}, 30), (Point2{10, 20}));  // end point on the plane
    EXPECT_EQ(interpolateEdge(low, {10, 20, 30}, 0), (Point2{0, 0}));
    // Extreme coordinates stay exact in 64 bits.
    const coord_um big = kMaxSliceCoordinateUm;
    EXPECT_EQ(interpolateEdge({-big, -big, -big}, {big, big, big}, 0), (Point2{0, 0}));
    EXPECT_EQ(interpolateEdge({-big, big, -big}, {big, -big, big}, big / 2), (Point2{big / 2, -big / 2}));
}

TEST(FacetPlaneInterpolation, BothFacetsOfAnEdgeComputeTheSamePoint) {
    // Edge (p, q) shared by two facets wound in opposite directions along it.
    const Point3 p{123, -457, 17}, q{9871, 3331, 1013}, r1{5000, -9000, 900}, r2{-4000, 7000, 100};
    for (coord_um z = 18; z < 1013; z += 37) {
        const auto s1 = cutFacet(p, q, r1, z, OnPlaneRule::CountAsAbove);
        const auto s2 = cutFacet(q, p, r2, z, OnPlaneRule::CountAsAbove);
        ASSERT_TRUE(s1 && s2);
        const Point2 on_edge = interpolateEdge(p, q, z);
        EXPECT_TRUE(s1->from == on_edge || s1->to == on_edge) << z;
        EXPECT_TRUE(s2->from == on_edge || s2->to == on_edge) << z;
    }
}

}  // namespace
}  // namespace mixengine

namespace mixengine {
namespace {

TEST(FacetPlanePrinted, LoneVertexCrossingRoundsTowardsTheLoneVertexAsCuraEngine) {
    // Exact crossings at x = 333.3 and 666.7: CuraEngine's quarter offset and truncation give 333 and 666.
    EXPECT_EQ(loneVertexCrossing({0, 0, 0}, {1000, 0, 3000}, 1000), (Point2{333, 0}));
    EXPECT_EQ(loneVertexCrossing({0, 0, 3000}, {1000, 0, 0}, 1000), (Point2{666, 0}));
    EXPECT_EQ(interpolateEdge({1000, 0, 0}, {0, 0, 3000}, 1000), (Point2{667, 0}));
}

TEST(FacetPlanePrinted, AVertexOnThePlaneIsLiftedByOneMicron) {
    // V1 on the plane counts as above (lifted to z 1001); V2 is alone below at z 0, V3 above.
    const auto segment =
        cutFacet({0, 0, 1000}, {1000, 0, 0}, {0, 1000, 2000}, 1000, OnPlaneRule::CountAsAbove);
    ASSERT_TRUE(segment.has_value());
    EXPECT_EQ(segment->from, (Point2{0, 0}));  // exact: the vertex itself
    // From (1000, 0, 0) to (0, 0, 1001): 1000 − (1000·1000 + 250) / 1001 = 1000 − 999 = 1 (the segment starts
    // there).
    EXPECT_EQ(segment->printed_from, (Point2{1, 0}));
}

}  // namespace
}  // namespace mixengine
