// One travel (planning/TravelRoute.h): combing, moving its ends inside, the combing limit, going
// around other parts, and which travels retract.
#include "planning/TravelRoute.h"

#include <gtest/gtest.h>

#include <cmath>

namespace mixengine {
namespace {

Path square(coord_um x0, coord_um y0, coord_um size) {
    return {{x0, y0}, {x0 + size, y0}, {x0 + size, y0 + size}, {x0, y0 + size}};
}

TravelParams params() {
    TravelParams p;
    p.retraction_enable = true;
    p.retraction_min_travel_um = 1'500;
    return p;
}

/// The space outside two 10 mm parts at x 0 and 30 mm, with a third one between them (x 15 … 25,
/// y 0 … 10 mm): a rectangle around them with the parts as holes.
Paths freeAroundThreeParts() {
    return {{{-5'000, -5'000}, {45'000, -5'000}, {45'000, 15'000}, {-5'000, 15'000}},
            square(0, 0, 10'000),
            square(15'000, 0, 10'000),
            square(30'000, 0, 10'000)};
}

TEST(TravelRoute, ShortTravelGoesStraightWithoutRetracting) {
    const CombBoundary comb({square(0, 0, 10'000)});
    TravelParams p = params();
    p.comb = &comb;
    const TravelRoute r = planTravel({1'000, 1'000}, {50'000, 1'000}, p);  // leaves the part, but is
    EXPECT_TRUE(r.retract);                                                // long: retracts
    const TravelRoute short_one = planTravel({1'000, 1'000}, {2'000, 1'500}, p);
    EXPECT_FALSE(short_one.retract);
    EXPECT_EQ(short_one.points, (Path{{2'000, 1'500}}));
}

TEST(TravelRoute, TravelTooShortToRetractStillCombsWhenNotShorterThanTheNozzleTip) {
    // A U: two 10 mm arms with a 0.6 mm slot between them (x 10 … 10.6 mm) down to y = 2 mm.
    const Path u{{0, 0},          {20'600, 0},     {20'600, 10'000}, {10'600, 10'000},
                 {10'600, 2'000}, {10'000, 2'000}, {10'000, 10'000}, {0, 10'000}};
    const CombBoundary comb(Paths{u});
    TravelParams p = params();
    p.comb = &comb;
    p.short_comb_min_um = 1'000;
    // 1.2 mm across the slot (under retraction_min_travel): around the slot's bottom, no retraction.
    const TravelRoute combed = planTravel({9'700, 9'000}, {10'900, 9'000}, p);
    EXPECT_FALSE(combed.retract);
    ASSERT_GE(combed.points.size(), 3U);
    EXPECT_EQ(combed.points.back(), (Point2{10'900, 9'000}));
    for (const Point2& q : combed.points)
        EXPECT_TRUE(comb.inside(q)) << q.X << "," << q.Y;
    double length = 0;
    Point2 at{9'700, 9'000};
    for (const Point2& q : combed.points)
        length += distanceUm(at, q), at = q;
    EXPECT_GT(length, 14'000.0);  // down to y ≈ 2 mm and up again
    // 0.9 mm across: shorter than the nozzle tip, straight over the slot.
    const TravelRoute straight = planTravel({9'850, 9'000}, {10'750, 9'000}, p);
    EXPECT_FALSE(straight.retract);
    EXPECT_EQ(straight.points, (Path{{10'750, 9'000}}));
}

TEST(TravelRoute, CombsInsideAndMovesEndsInFromNearby) {
    const CombBoundary comb({square(0, 0, 10'000)});
    TravelParams p = params();
    p.comb = &comb;
    const TravelRoute inside = planTravel({1'000, 1'000}, {9'000, 9'000}, p);
    EXPECT_FALSE(inside.retract);
    EXPECT_EQ(inside.points, (Path{{9'000, 9'000}}));
    // The end is 0.5 mm outside: without reach it goes through the air and retracts; with 1.6 mm of
    // reach the travel combs to the edge (20 µm inside) and moves out to it.
    EXPECT_TRUE(planTravel({1'000, 5'000}, {10'500, 5'000}, p).retract);
    p.comb_move_inside_um = 1'600;
    const TravelRoute moved = planTravel({1'000, 5'000}, {10'500, 5'000}, p);
    EXPECT_FALSE(moved.retract);
    EXPECT_EQ(moved.points, (Path{{9'980, 5'000}, {10'500, 5'000}}));
    // retraction_combing_max_distance: a combed travel longer than it retracts.
    p.combing_max_distance_um = 5'000;
    EXPECT_TRUE(planTravel({1'000, 1'000}, {9'000, 9'000}, p).retract);
}

/// A regular 32-gon ring of radii r_in … r_out µm around the origin, a corner at (0, r).
Paths ring(double r_in, double r_out) {
    Paths loops(2);
    for (int k = 0; k < 32; ++k) {
        const double angle = 2 * 3.14159265358979 * k / 32 + 3.14159265358979 / 2;
        loops[0].push_back({std::llround(r_out * std::cos(angle)), std::llround(r_out * std::sin(angle))});
        loops[1].insert(loops[1].begin(),
                        Point2{std::llround(r_in * std::cos(angle)), std::llround(r_in * std::sin(angle))});
    }
    return loops;
}

TEST(TravelRoute, BetweenTwoRingsThroughTheirCornersRetracts) {
    // A tube's walls over its skin: the outline's walls (r 4.19 … 4.6 mm) and the hole's (r 2.4 …
    // 2.81 mm) apart; the travel from one to the other along x = 0 meets both boundaries at corners.
    Paths area = ring(4'190, 4'600);
    const Paths hole = ring(2'400, 2'810);
    area.insert(area.end(), hole.begin(), hole.end());
    const CombBoundary comb(area);
    TravelParams p = params();
    p.comb = &comb;
    p.comb_move_inside_um = 1'600;
    EXPECT_TRUE(planTravel({0, 4'800}, {0, 2'600}, p).retract);  // from the outer wall's centre line
    EXPECT_TRUE(planTravel({0, 4'400}, {0, 2'600}, p).retract);
    p.retraction_min_travel_um = 2'250;  // shorter than that: no retraction
    EXPECT_FALSE(planTravel({0, 4'800}, {0, 2'600}, p).retract);
}

TEST(TravelRoute, ThroughTheAirAroundTheOtherParts) {
    const CombBoundary free(freeAroundThreeParts());
    TravelParams p = params();
    p.free = &free;
    // From the left part to the right one: out of the left part, around the middle one, in.
    const TravelRoute r = planTravel({5'000, 5'000}, {35'000, 5'000}, p);
    EXPECT_TRUE(r.retract);
    ASSERT_GE(r.points.size(), 4U);
    EXPECT_EQ(r.points.front(), (Point2{10'020, 5'000}));
    EXPECT_EQ(r.points.back(), (Point2{35'000, 5'000}));
    for (const Point2& q : r.points)  // never through the middle part
        EXPECT_FALSE(q.X > 15'000 && q.X < 25'000 && q.Y > 0 && q.Y < 10'000) << q.X << "," << q.Y;
    p.free = nullptr;  // travel_avoid_other_parts off: straight
    EXPECT_EQ(planTravel({5'000, 5'000}, {35'000, 5'000}, p).points, (Path{{35'000, 5'000}}));
}

TEST(TravelRoute, SupportToSupportClearOfThePartsNeedNotRetract) {
    const CombBoundary free(freeAroundThreeParts());
    TravelParams p = params();
    p.free = &free;
    p.limit_support_retractions = true;
    EXPECT_FALSE(planTravel({0, 12'000}, {40'000, 12'000}, p).retract);  // above the parts, clear
    EXPECT_TRUE(planTravel({0, -2'000}, {40'000, 12'000}, p).retract);   // across the parts
    p.limit_support_retractions = false;
    EXPECT_TRUE(planTravel({0, 12'000}, {40'000, 12'000}, p).retract);
    const CombBoundary comb({square(0, 0, 10'000)});
    p.limit_support_retractions = true;
    p.comb = &comb;  // a mesh travel through the air always retracts
    EXPECT_TRUE(planTravel({0, 12'000}, {40'000, 12'000}, p).retract);
}

TEST(TravelRoute, WayPointsCloserThanTheTravelResolutionAreLeftOut) {
    // From (0,0): (300,0) is within 0.5 mm of the start, (800,0) is not; (1'000,0) is within 0.5 mm of
    // (800,0); (2'000,0) is kept; the end (2'100,0) is kept however close.
    const Path way{{300, 0}, {800, 0}, {1'000, 0}, {2'000, 0}, {2'100, 0}};
    EXPECT_EQ(thinTravel({0, 0}, way, 500, false), (Path{{800, 0}, {2'000, 0}, {2'100, 0}}));
    // A start moved into the comb area is kept, and the next point is measured from it.
    EXPECT_EQ(thinTravel({0, 0}, way, 500, true), (Path{{300, 0}, {1'000, 0}, {2'000, 0}, {2'100, 0}}));
    EXPECT_EQ(thinTravel({0, 0}, way, 0, false), way);  // 0: every point
    // A combed travel around a notch: with a coarse resolution only the end is left.
    const Paths notch{{{0, 0},
                       {10'000, 0},
                       {10'000, 10'000},
                       {6'000, 10'000},
                       {6'000, 2'000},
                       {4'000, 2'000},
                       {4'000, 10'000},
                       {0, 10'000}}};
    const CombBoundary comb(notch);
    TravelParams p = params();
    p.comb = &comb;
    const TravelRoute fine = planTravel({2'000, 9'000}, {8'000, 9'000}, p);
    ASSERT_GE(fine.points.size(), 3U);
    p.max_travel_resolution_um = 20'000;
    EXPECT_EQ(planTravel({2'000, 9'000}, {8'000, 9'000}, p).points, (Path{{8'000, 9'000}}));
}

}  // namespace
}  // namespace mixengine
