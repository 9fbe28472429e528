// Ordering one layer's paths (planning/PathOrder.h): nearest start, ;TYPE: changes, retraction on
// long travels, and the extruded volume.
#include "planning/PathOrder.h"

#include <gtest/gtest.h>

namespace mixengine {
namespace {

ExtrusionPath line(Point2 a, Point2 b, Feature feature = Feature::Fill) {
    ExtrusionPath p;
    p.points = {a, b};
    p.width_um = 400;
    p.feature = feature;
    p.speed_mm_s = 60;
    return p;
}

ExtrusionPath loop(Path points, Feature feature = Feature::WallOuter) {
    ExtrusionPath p;
    p.points = std::move(points);
    p.closed = true;
    p.width_um = 400;
    p.feature = feature;
    p.speed_mm_s = 30;
    return p;
}

TravelParams travelParams() {
    TravelParams t;
    t.travel_speed_mm_s = 150;
    t.retraction_enable = true;
    t.retraction_min_travel_um = 1'500;
    t.layer_thickness_um = 200;
    return t;
}

void expectStep(const PlanStep& s, PlanStep::Kind kind, Point2 to) {
    EXPECT_EQ(s.kind, kind);
    EXPECT_EQ(s.to, to);
}

TEST(PathOrder, NearestEndOfLinesAndNearestVertexOfLoops) {
    const Path square{{30'000, 0}, {40'000, 0}, {40'000, 10'000}, {30'000, 10'000}};
    std::vector<ExtrusionPath> paths{loop(square, Feature::Fill), line({20'000, 0}, {10'000, 0})};
    Point2 head{0, 0};
    std::optional<Feature> feature;
    std::vector<PlanStep> steps;
    appendOrderedPaths(paths, travelParams(), head, feature, steps);
    ASSERT_EQ(steps.size(), 8U);
    EXPECT_EQ(steps[0].kind, PlanStep::Kind::SetFeature);
    EXPECT_EQ(steps[0].feature, Feature::Fill);
    expectStep(steps[1], PlanStep::Kind::Travel, {10'000, 0});  // the line's nearer end
    EXPECT_TRUE(steps[1].retract);
    EXPECT_EQ(steps[1].speed_mm_s, 150.0);
    expectStep(steps[2], PlanStep::Kind::Extrude, {20'000, 0});
    EXPECT_EQ(steps[2].speed_mm_s, 60.0);
    EXPECT_DOUBLE_EQ(steps[2].volume_mm3, 10.0 * 0.4 * 0.2);
    expectStep(steps[3], PlanStep::Kind::Travel, {30'000, 0});  // the loop's nearest vertex
    expectStep(steps[4], PlanStep::Kind::Extrude, {40'000, 0});
    expectStep(steps[5], PlanStep::Kind::Extrude, {40'000, 10'000});
    expectStep(steps[6], PlanStep::Kind::Extrude, {30'000, 10'000});
    expectStep(steps[7], PlanStep::Kind::Extrude, {30'000, 0});  // closed: back to the start
    EXPECT_EQ(head, (Point2{30'000, 0}));
    EXPECT_EQ(feature, Feature::Fill);
}

TEST(PathOrder, LoopStartsAtTheVertexNearestTheHead) {
    Point2 head{41'000, 11'000};
    std::optional<Feature> feature = Feature::WallOuter;
    std::vector<PlanStep> steps;
    appendOrderedPaths({loop({{30'000, 0}, {40'000, 0}, {40'000, 10'000}, {30'000, 10'000}})}, travelParams(),
                       head, feature, steps);
    ASSERT_EQ(steps.size(), 5U);  // no ;TYPE: (feature unchanged), travel, four sides
    expectStep(steps[0], PlanStep::Kind::Travel, {40'000, 10'000});
    EXPECT_FALSE(steps[0].retract);  // √2 mm < 1.5 mm
    expectStep(steps[1], PlanStep::Kind::Extrude, {30'000, 10'000});
    expectStep(steps[4], PlanStep::Kind::Extrude, {40'000, 10'000});
    EXPECT_DOUBLE_EQ(steps[1].volume_mm3, 10.0 * 0.4 * 0.2);
}

TEST(PathOrder, OneFeatureMarkerPerChange) {
    std::vector<ExtrusionPath> paths{
        line({7'000, 0}, {7'000, 500}, Feature::Fill), line({1'000, 0}, {1'000, 500}, Feature::Fill),
        line({5'000, 0}, {5'000, 500}, Feature::Skin), line({3'000, 0}, {3'000, 500}, Feature::Fill)};
    Point2 head{0, 0};
    std::optional<Feature> feature = Feature::Fill;
    std::vector<PlanStep> steps;
    appendOrderedPaths(paths, travelParams(), head, feature, steps);
    std::vector<Feature> markers;
    std::vector<coord_um> starts;
    for (const PlanStep& s : steps) {
        if (s.kind == PlanStep::Kind::SetFeature)
            markers.push_back(s.feature);
        if (s.kind == PlanStep::Kind::Travel)
            starts.push_back(s.to.X);
    }
    EXPECT_EQ(starts, (std::vector<coord_um>{1'000, 3'000, 5'000, 7'000}));
    EXPECT_EQ(markers, (std::vector<Feature>{Feature::Skin, Feature::Fill}));
    EXPECT_EQ(feature, Feature::Fill);
}

TEST(PathOrder, ASequenceIsEnteredAtItsFirstPathAndPrintedInOrder) {
    // Three lines of sequence 1 listed far-middle-near, and a free line between: the head is nearest
    // to the sequence's last line, but the sequence is entered at its first path and printed as
    // listed, each line from its end nearer to the head; the free line comes after.
    std::vector<ExtrusionPath> paths{line({9'000, 0}, {9'000, 5'000}), line({6'000, 0}, {6'000, 5'000}),
                                     line({3'000, 0}, {3'000, 5'000}), line({1'000, 0}, {1'000, 5'000})};
    for (std::size_t i = 0; i < 3; ++i)
        paths[i].sequence = 1;
    Point2 head{12'000, 0};
    std::optional<Feature> feature = Feature::Fill;
    std::vector<PlanStep> steps;
    appendOrderedPaths(paths, travelParams(), head, feature, steps);
    std::vector<Point2> starts;
    for (const PlanStep& s : steps) {
        if (s.kind == PlanStep::Kind::Travel)
            starts.push_back(s.to);
    }
    EXPECT_EQ(starts, (std::vector<Point2>{{9'000, 0}, {6'000, 5'000}, {3'000, 0}, {1'000, 5'000}}));
    // Without the sequence the same lines go nearest-first: the same order here, but entered
    // anywhere: from a head at the far left the free line and then 3, 6, 9 mm.
    for (ExtrusionPath& path : paths)
        path.sequence = 0;
    head = {0, 0};
    steps.clear();
    appendOrderedPaths(paths, travelParams(), head, feature, steps);
    EXPECT_EQ(steps.front().to, (Point2{1'000, 0}));
}

TEST(PathOrder, KeepOrderPrintsTheGroupAsGivenFromTheNearerEnds) {
    // Nearest first would take x = 1, 3, 5 mm; kept in order (monotonic ironing) it is 5, 1, 3 mm, each
    // line entered from its end nearer the nozzle (the second ends at y = 0, so the third starts there).
    std::vector<ExtrusionPath> paths{line({5'000, 0}, {5'000, 500}, Feature::Ironing),
                                     line({1'000, 500}, {1'000, 0}, Feature::Ironing),
                                     line({3'000, 0}, {3'000, 500}, Feature::Ironing)};
    for (ExtrusionPath& p : paths)
        p.keep_order = true;
    Point2 head{0, 0};
    std::optional<Feature> feature;
    std::vector<PlanStep> steps;
    appendOrderedPaths(paths, travelParams(), head, feature, steps);
    std::vector<Point2> travels;
    for (const PlanStep& s : steps) {
        if (s.kind == PlanStep::Kind::Travel)
            travels.push_back(s.to);
    }
    EXPECT_EQ(travels, (std::vector<Point2>{{5'000, 0}, {1'000, 500}, {3'000, 0}}));
    EXPECT_EQ(steps[0].feature, Feature::Ironing);
}

TEST(PathOrder, RetractOnlyForTravelsLongerThanTheMinimum) {
    struct Case {
        coord_um start_x;
        bool enable;
        bool retract;
    };
    const Case cases[] = {
        {1'000, true, false}, {1'500, true, false}, {1'501, true, true}, {10'000, false, false}};
    for (const Case& c : cases) {
        TravelParams t = travelParams();
        t.retraction_enable = c.enable;
        Point2 head{0, 0};
        std::optional<Feature> feature = Feature::Fill;
        std::vector<PlanStep> steps;
        appendOrderedPaths({line({c.start_x, 0}, {c.start_x + 5'000, 0})}, t, head, feature, steps);
        ASSERT_EQ(steps.size(), 2U) << c.start_x;
        EXPECT_EQ(steps[0].retract, c.retract) << c.start_x << " enable " << c.enable;
    }
}

TEST(PathOrder, DegeneratePathsAndEmptyInput) {
    ExtrusionPath single;
    single.points = {{5'000, 5'000}};
    Point2 head{0, 0};
    std::optional<Feature> feature;
    std::vector<PlanStep> steps;
    appendOrderedPaths({single, ExtrusionPath{}}, travelParams(), head, feature, steps);
    appendOrderedPaths({}, travelParams(), head, feature, steps);
    EXPECT_TRUE(steps.empty());
    EXPECT_EQ(head, (Point2{0, 0}));
    EXPECT_FALSE(feature.has_value());
}

TEST(PathOrder, FlowScalesTheVolume) {
    ExtrusionPath p = line({0, 0}, {3'000, 4'000});
    p.width_um = 450;
    p.flow = 0.9;
    TravelParams t = travelParams();
    t.layer_thickness_um = 100;
    Point2 head{0, 0};
    std::optional<Feature> feature = Feature::Fill;
    std::vector<PlanStep> steps;
    appendOrderedPaths({p}, t, head, feature, steps);
    ASSERT_EQ(steps.size(), 2U);
    EXPECT_DOUBLE_EQ(steps[1].volume_mm3, 5.0 * 0.45 * 0.1 * 0.9);
}

TEST(PathOrder, ExtrusionVolume) {
    EXPECT_EQ(extrusionVolumeMm3({0, 0}, {10'000, 0}, 400, 200, 1.0), 0.8);
    EXPECT_DOUBLE_EQ(extrusionVolumeMm3({0, 0}, {3'000, 4'000}, 450, 100, 0.9), 0.2025);
    EXPECT_DOUBLE_EQ(extrusionVolumeMm3({-1'000, -1'000}, {-1'000, 1'000}, 400, 300, 1.0), 2.0 * 0.4 * 0.3);
    EXPECT_EQ(extrusionVolumeMm3({7, 7}, {7, 7}, 400, 200, 1.0), 0.0);
}

}  // namespace
}  // namespace mixengine

namespace mixengine {
namespace {

/// The first extrusion's start: where the first path printed begins.
Point2 firstPrinted(const std::vector<PlanStep>& steps) {
    Point2 at{0, 0};
    for (const PlanStep& s : steps) {
        if (s.kind == PlanStep::Kind::Extrude)
            return at;
        if (s.kind == PlanStep::Kind::Travel)
            at = s.to;
    }
    return at;
}

TEST(PathOrder, OrderFromMovesTheFirstSearchNotTheTravel) {
    std::vector<ExtrusionPath> paths{line({1'000, 0}, {2'000, 0}), line({50'000, 0}, {51'000, 0})};
    TravelParams t = travelParams();
    t.order_from = Point2{51'000, 10};  // the far line's end is chosen first
    Point2 head{0, 0};
    std::optional<Feature> feature;
    std::vector<PlanStep> steps;
    appendOrderedPaths(paths, t, head, feature, steps);
    EXPECT_EQ(firstPrinted(steps), Point2(51'000, 0));
    ASSERT_EQ(steps[1].kind, PlanStep::Kind::Travel);  // after the ;TYPE: marker, from the head
    EXPECT_TRUE(steps[1].retract);
}

TEST(PathOrder, CombAwareOrderPrefersWhatCanBeReachedInside) {
    // A U-shaped part with a 2 mm gap: the head at the top of the left arm, a line 3 mm away across
    // the gap (a 40 mm travel round the bottom inside the part) and one 7.5 mm up the left arm.
    const Paths u{{{0, 0},
                   {22'000, 0},
                   {22'000, 40'000},
                   {12'000, 40'000},
                   {12'000, 10'000},
                   {10'000, 10'000},
                   {10'000, 40'000},
                   {0, 40'000}}};
    const CombBoundary comb(u);
    std::vector<ExtrusionPath> paths{line({12'500, 30'000}, {20'000, 30'000}),
                                     line({5'000, 36'000}, {1'000, 36'000})};
    TravelParams t = travelParams();
    t.comb = &comb;
    for (bool aware : {false, true}) {
        t.comb_aware_order = aware;
        Point2 head{9'500, 30'000};
        std::optional<Feature> feature;
        std::vector<PlanStep> steps;
        appendOrderedPaths(paths, t, head, feature, steps);
        EXPECT_EQ(firstPrinted(steps), aware ? Point2(5'000, 36'000) : Point2(12'500, 30'000)) << aware;
    }
}

}  // namespace
}  // namespace mixengine
