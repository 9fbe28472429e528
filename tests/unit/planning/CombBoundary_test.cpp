// Combing (planning/CombBoundary.h): inside tests, straight travel, routes around holes.
#include "planning/CombBoundary.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace mixengine {
namespace {

Path square(coord_um x0, coord_um y0, coord_um size, bool ccw = true) {
    Path p{{x0, y0}, {x0 + size, y0}, {x0 + size, y0 + size}, {x0, y0 + size}};
    if (!ccw)
        std::reverse(p.begin(), p.end());
    return p;
}

/// A 30 mm square with a 10 mm square hole in the middle.
Paths squareWithHole() {
    return {square(0, 0, 30'000), square(10'000, 10'000, 10'000, false)};
}

double length(Point2 from, const Path& points) {
    double sum = 0;
    for (const Point2& p : points) {
        sum += std::hypot(double(p.X - from.X), double(p.Y - from.Y));
        from = p;
    }
    return sum;
}

TEST(CombBoundary, InsideOutsideAndHole) {
    const CombBoundary comb(squareWithHole());
    EXPECT_TRUE(comb.inside({5'000, 5'000}));
    EXPECT_TRUE(comb.inside({0, 15'000}));        // on the boundary
    EXPECT_FALSE(comb.inside({15'000, 15'000}));  // in the hole
    EXPECT_FALSE(comb.inside({-1, 15'000}));
    EXPECT_FALSE(comb.inside({31'000, 5'000}));
}

/// Even-odd inside, boundary included, by ClipperLib (an independent point-in-polygon test).
bool insideEvenOdd(const Paths& loops, const Point2& p) {
    bool odd = false;
    for (const Path& loop : loops) {
        const int where = ClipperLib::PointInPolygon(p, loop);
        if (where < 0)
            return true;
        odd = odd != (where == 1);
    }
    return odd;
}

/// A 60-point star (radii 20 and 50 mm) with 30 square holes of 0.6 mm in a row across its middle.
Paths starWithHoles() {
    Paths loops(1);
    for (int k = 0; k < 60; ++k) {
        const double angle = 2 * 3.14159265358979 * k / 60, radius = k % 2 ? 20'000.0 : 50'000.0;
        loops[0].push_back({std::llround(radius * std::cos(angle)), std::llround(radius * std::sin(angle))});
    }
    for (int k = 0; k < 30; ++k)
        loops.push_back(square(-15'000 + k * 1'000, -300, 600, false));
    return loops;
}

TEST(CombBoundary, InsideAgreesWithPointInPolygonOnBothSidesOfTheGrid) {
    // Many grid cells, both ray directions used.
    const Paths loops = starWithHoles();
    const CombBoundary comb(loops);
    std::uint64_t state = 12345;
    auto next = [&] { return (state = state * 6364136223846793005ULL + 1442695040888963407ULL) >> 33; };
    int inside = 0;
    for (int n = 0; n < 20'000; ++n) {
        // Grid-aligned coordinates too (multiples of 100 µm), so points land on vertices and edges.
        const Point2 p =
            n % 2 ? Point2{coord_um(next() % 110'000) - 55'000, coord_um(next() % 110'000) - 55'000}
                  : Point2{coord_um(next() % 1'100) * 100 - 55'000, coord_um(next() % 21) * 100 - 1'000};
        ASSERT_EQ(comb.inside(p), insideEvenOdd(loops, p)) << p.X << ", " << p.Y;
        inside += comb.inside(p);
    }
    EXPECT_GT(inside, 2'000);
    EXPECT_LT(inside, 18'000);
}

/// A 600-vertex star on a 100 µm lattice, 10 mm across, with a lattice square hole: so many edges
/// in so small an area that the grid's cells are 0.5 mm, their centres 50 µm off the lattice, so
/// that edges pass through them and vertices lie on the lines from them to points of a 50 µm
/// lattice.
Paths latticeStar() {
    Paths loops(1);
    std::uint64_t state = 99;
    auto next = [&] { return (state = state * 6364136223846793005ULL + 1442695040888963407ULL) >> 33; };
    for (int k = 0; k < 600; ++k) {
        const double angle = 2 * 3.14159265358979 * k / 600, radius = 1'000.0 + double(next() % 41) * 100.0;
        loops[0].push_back({std::llround(radius * std::cos(angle) / 100) * 100,
                            std::llround(radius * std::sin(angle) / 100) * 100});
    }
    loops.push_back(square(-500, -500, 1'000, false));
    return loops;
}

TEST(CombBoundary, InsideAgreesWithPointInPolygonWhereEdgesPassThroughCellCentres) {
    const Paths loops = latticeStar();
    const CombBoundary comb(loops);
    int inside = 0, points = 0;
    for (coord_um x = -5'250; x <= 5'250; x += 50) {
        for (coord_um y = -5'250; y <= 5'250; y += 50) {
            ASSERT_EQ(comb.inside({x, y}), insideEvenOdd(loops, {x, y})) << x << ", " << y;
            inside += comb.inside({x, y});
            ++points;
        }
    }
    EXPECT_GT(inside, points / 10);
    EXPECT_LT(inside, points * 9 / 10);
}

/// The segments p–q and a–b cross at a point inside both (doubles are exact at these sizes).
bool crossProperly(const Point2& p, const Point2& q, const Point2& a, const Point2& b) {
    auto side = [](const Point2& o, const Point2& d, const Point2& x) {
        const double cross = double(d.X - o.X) * double(x.Y - o.Y) - double(d.Y - o.Y) * double(x.X - o.X);
        return cross > 0 ? 1 : (cross < 0 ? -1 : 0);
    };
    return side(p, q, a) * side(p, q, b) < 0 && side(a, b, p) * side(a, b, q) < 0;
}

TEST(CombBoundary, StraightInsideAgreesWithTestingEveryEdge) {
    // Segments of every length and direction, long diagonals included, so the cells along a
    // segment (not its bounding box) must hold every edge it crosses.
    const Paths loops = starWithHoles();
    const CombBoundary comb(loops);
    std::uint64_t state = 777;
    auto next = [&] {
        return coord_um((state = state * 6364136223846793005ULL + 1442695040888963407ULL) >> 33);
    };
    int straight = 0;
    for (int n = 0; n < 20'000; ++n) {
        const Point2 a{next() % 80'000 - 40'000, next() % 80'000 - 40'000};
        const Point2 b{next() % 80'000 - 40'000, n % 3 ? next() % 80'000 - 40'000 : a.Y};
        const Point2 middle{a.X + (b.X - a.X) / 2, a.Y + (b.Y - a.Y) / 2};
        bool expected = insideEvenOdd(loops, a) && insideEvenOdd(loops, b) && insideEvenOdd(loops, middle);
        for (const Path& loop : loops) {
            for (std::size_t i = 0; expected && i < loop.size(); ++i)
                expected = !crossProperly(a, b, loop[i], loop[(i + 1) % loop.size()]);
        }
        ASSERT_EQ(comb.straightInside(a, b), expected) << a.X << "," << a.Y << " " << b.X << "," << b.Y;
        straight += expected;
    }
    EXPECT_GT(straight, 500);
    EXPECT_LT(straight, 19'500);
}

TEST(CombBoundary, StraightTravel) {
    const CombBoundary comb(squareWithHole());
    EXPECT_TRUE(comb.straightInside({5'000, 5'000}, {25'000, 5'000}));
    EXPECT_FALSE(comb.straightInside({5'000, 15'000}, {25'000, 15'000}));  // across the hole
}

TEST(CombBoundary, RoutesAroundTheHoleOnItsShorterSide) {
    const CombBoundary comb(squareWithHole());
    const auto route = comb.route({5'000, 14'000}, {25'000, 14'000});
    ASSERT_TRUE(route.has_value());
    EXPECT_EQ(route->back(), (Point2{25'000, 14'000}));
    // Below the hole: 5→(10,10): √(25+16) mm, 10 mm along the edge, (20,10)→25: √(25+16).
    EXPECT_NEAR(length({5'000, 14'000}, *route), 10'000 + 2 * std::sqrt(41.0) * 1000, 1.0);
    Point2 from{5'000, 14'000};
    for (const Point2& p : *route) {
        EXPECT_TRUE(comb.straightInside(from, p));
        from = p;
    }
}

TEST(CombBoundary, NoRouteBetweenIslandsOrFromOutside) {
    const CombBoundary comb({square(0, 0, 10'000), square(20'000, 0, 10'000)});
    EXPECT_FALSE(comb.route({5'000, 5'000}, {25'000, 5'000}).has_value());
    EXPECT_FALSE(comb.route({15'000, 5'000}, {5'000, 5'000}).has_value());
    EXPECT_TRUE(comb.route({1'000, 5'000}, {9'000, 5'000}).has_value());
}

/// A regular polygon of `corners` corners at radius `radius_um` around (cx, cy), one corner straight
/// above the centre (x = cx exactly), counter-clockwise unless `hole`.
Path regularPolygon(coord_um cx, coord_um cy, double radius_um, int corners, bool hole = false) {
    Path loop;
    for (int k = 0; k < corners; ++k) {
        const double angle = 2 * 3.14159265358979 * k / corners + 3.14159265358979 / 2;
        loop.push_back(
            {cx + std::llround(radius_um * std::cos(angle)), cy + std::llround(radius_um * std::sin(angle))});
    }
    if (hole)
        std::reverse(loop.begin(), loop.end());
    return loop;
}

/// A tube's two wall rings, as a comb area over skin: r 4.19 … 4.6 mm and r 2.4 … 2.81 mm.
Paths twoRings() {
    return {regularPolygon(0, 0, 4'600, 64), regularPolygon(0, 0, 4'190, 64, true),
            regularPolygon(0, 0, 2'810, 32), regularPolygon(0, 0, 2'400, 32, true)};
}

TEST(CombBoundary, ATravelThroughCornersCrossesTheBoundaryThere) {
    const CombBoundary comb(twoRings());
    // From the outer ring to the inner one along x = 0, through a corner of each ring's boundary
    // (r 4.19 and r 2.81): two islands, no route, not straight inside.
    const Point2 outer{0, 4'400}, inner{0, 2'600};
    ASSERT_EQ(twoRings()[1].back(), (Point2{0, 4'190}));
    ASSERT_TRUE(comb.inside(outer));
    ASSERT_TRUE(comb.inside(inner));
    EXPECT_FALSE(comb.route(outer, inner).has_value());
    EXPECT_FALSE(comb.straightInside(outer, inner));
    EXPECT_TRUE(comb.crossesBoundary(outer, inner));
    // Across the tube's hole, corner to corner: around the inner ring's hole, on the ring.
    const auto around = comb.route({0, 2'600}, {0, -2'600});
    ASSERT_TRUE(around.has_value());
    Point2 from{0, 2'600};
    for (const Point2& p : *around) {  // each leg inside (along the hole's edges: on them)
        EXPECT_TRUE(comb.inside(p)) << p.X << "," << p.Y;
        EXPECT_FALSE(comb.crossesBoundary(from, p)) << p.X << "," << p.Y;
        from = p;
    }
    EXPECT_GT(length({0, 2'600}, *around), 2 * 2'400);
}

TEST(CombBoundary, ATravelTouchingACornerOrRunningAlongAnEdgeStaysInside) {
    // A square with a notch from the top whose tip (10, 6) is a corner the travel y = 6 touches,
    // and a step whose edge y = 2 the travel y = 2 runs along.
    const CombBoundary comb(Paths{{{0, 0},
                                   {4'000, 0},
                                   {4'000, 2'000},
                                   {8'000, 2'000},
                                   {8'000, 0},
                                   {20'000, 0},
                                   {20'000, 20'000},
                                   {11'000, 20'000},
                                   {10'000, 6'000},
                                   {9'000, 20'000},
                                   {0, 20'000}}});
    EXPECT_TRUE(comb.straightInside({2'000, 6'000}, {18'000, 6'000}));
    EXPECT_FALSE(comb.crossesBoundary({2'000, 6'000}, {18'000, 6'000}));
    EXPECT_TRUE(comb.straightInside({1'000, 2'000}, {12'000, 2'000}));
    // Through the step's corners into the gap below it: crosses.
    EXPECT_FALSE(comb.straightInside({6'000, 1'000}, {6'000, 3'000}));
    EXPECT_FALSE(comb.straightInside({2'000, 4'000}, {6'000, 0}));
    const auto route = comb.route({2'000, 6'000}, {18'000, 6'000});
    ASSERT_TRUE(route.has_value());
    EXPECT_EQ(*route, (Path{{18'000, 6'000}}));
}

/// Whether the segment a–b stays in the closed even-odd area of `loops`: a, b and the middle of
/// every piece between the points where it meets a loop (a corner, a crossing) are inside; nothing
/// when a piece is shorter than 10 µm (its rounded middle may fall on either side).
std::optional<bool> staysInside(const Paths& loops, const Point2& a, const Point2& b) {
    const double dx = double(b.X - a.X), dy = double(b.Y - a.Y), length = std::hypot(dx, dy);
    std::vector<double> ts{0.0, 1.0};
    for (const Path& loop : loops) {
        for (std::size_t i = 0; i < loop.size(); ++i) {
            const Point2& p = loop[i];
            const Point2& q = loop[(i + 1) % loop.size()];
            const double ex = double(q.X - p.X), ey = double(q.Y - p.Y), den = dx * ey - dy * ex;
            if (den != 0) {
                const double t = (double(p.X - a.X) * ey - double(p.Y - a.Y) * ex) / den;
                const double u = (double(p.X - a.X) * dy - double(p.Y - a.Y) * dx) / den;
                if (t > 0 && t < 1 && u >= 0 && u <= 1)
                    ts.push_back(t);
            }
            const double tp = (double(p.X - a.X) * dx + double(p.Y - a.Y) * dy) / (length * length);
            if (tp > 0 && tp < 1)
                ts.push_back(tp);  // a corner's projection: where the pieces may change side
        }
    }
    std::sort(ts.begin(), ts.end());
    if (!insideEvenOdd(loops, a) || !insideEvenOdd(loops, b))
        return false;
    for (std::size_t k = 0; k + 1 < ts.size(); ++k) {
        const double piece = (ts[k + 1] - ts[k]) * length;
        if (piece < 0.01)
            continue;  // the same point twice
        if (piece < 10)
            return std::nullopt;
        const double t = (ts[k] + ts[k + 1]) / 2;
        if (!insideEvenOdd(loops, {a.X + std::llround(t * dx), a.Y + std::llround(t * dy)}))
            return false;
    }
    return true;
}

TEST(CombBoundary, StraightInsideThroughCornersAgreesWithThePiecesBetweenThem) {
    // Segments through a corner of the rings or the star (random directions, both ends at random
    // distances), so that most meet the boundary at a corner exactly.
    Paths loops = twoRings();
    for (Path& loop : loops) {
        for (Point2& p : loop)
            p.X += 60'000;
    }
    const Paths star = starWithHoles();
    loops.insert(loops.end(), star.begin(), star.end());
    const CombBoundary comb(loops);
    std::uint64_t state = 4242;
    auto next = [&] {
        return coord_um((state = state * 6364136223846793005ULL + 1442695040888963407ULL) >> 33);
    };
    int straight = 0, crossing = 0;
    for (int n = 0; n < 20'000; ++n) {
        const Path& loop = loops[std::size_t(next()) % loops.size()];
        const Point2 corner = loop[std::size_t(next()) % loop.size()];
        const Point2 step{next() % 41 - 20, next() % 41 - 20};
        if (step.X == 0 && step.Y == 0)
            continue;
        const coord_um before = next() % 400 + 1, after = next() % 400 + 1;
        const Point2 a{corner.X - before * step.X, corner.Y - before * step.Y};
        const Point2 b{corner.X + after * step.X, corner.Y + after * step.Y};
        const std::optional<bool> stays = staysInside(loops, a, b);
        if (!stays)
            continue;
        const bool expected = *stays;
        ASSERT_EQ(comb.straightInside(a, b), expected) << a.X << "," << a.Y << " " << b.X << "," << b.Y;
        straight += expected;
        crossing += insideEvenOdd(loops, a) && insideEvenOdd(loops, b) && !expected;
    }
    EXPECT_GT(straight, 1'000);
    EXPECT_GT(crossing, 1'000);
}

TEST(CombBoundary, InsideIsExactWhereDoublesRoundTheCrossing) {
    // A sliver whose right edge leans 1 µm over 10^12 µm, far from the origin: at y = 1 the edge
    // lies 10^-12 µm left of p, which a double (53 bits at 10^15) rounds onto p.
    constexpr coord_um kFar = 1'000'000'000'000'000;
    const CombBoundary comb(Paths{{{kFar + 1, 0}, {kFar, 1'000'000'000'000}, {kFar - 1'000'000, 0}}});
    EXPECT_FALSE(comb.inside({kFar + 1, 1}));
    EXPECT_TRUE(comb.inside({kFar, 1}));
    EXPECT_TRUE(comb.inside({kFar + 1, 0}));  // the corner: on the boundary
}

TEST(CombBoundary, EmptyBoundaryHasNothingInside) {
    const CombBoundary comb;
    EXPECT_TRUE(comb.empty());
    EXPECT_FALSE(comb.inside({0, 0}));
}

TEST(CombBoundary, EntryTowardAPointAndMovingInside) {
    const CombBoundary comb(squareWithHole());
    // From the hole towards the right: enters at x = 20 mm, 20 µm further in.
    EXPECT_EQ(comb.entryToward({15'000, 15'000}, {25'000, 15'000}), (Point2{20'020, 15'000}));
    EXPECT_EQ(comb.entryToward({-5'000, 5'000}, {5'000, 5'000}), (Point2{20, 5'000}));
    EXPECT_FALSE(comb.entryToward({-5'000, -5'000}, {-1'000, -5'000}).has_value());  // never enters
    // Inside stays; 1 mm into the hole from its edge comes back out to the edge and 20 µm on.
    EXPECT_EQ(comb.moveInside({5'000, 5'000}, 1'000), (Point2{5'000, 5'000}));
    EXPECT_EQ(comb.moveInside({11'000, 15'000}, 1'500), (Point2{9'980, 15'000}));
    EXPECT_FALSE(comb.moveInside({15'000, 15'000}, 1'500).has_value());  // 5 mm from any edge
}

}  // namespace
}  // namespace mixengine
