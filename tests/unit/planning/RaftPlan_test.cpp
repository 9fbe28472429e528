// Planning a print on a raft (planning/PrintPlanner.h): the raft's layers come first with their
// negative numbers, thickness, fan and features, the base's loop before its lines, travel combing
// inside the raft; the model follows from layer 0, lifted.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "../toolpaths/ToolpathTestSupport.h"
#include "geometry/PolygonOps.h"
#include "planning/PrintPlanner.h"

namespace mixengine {
namespace {

/// A cube on a raft, planned.
struct RaftPrint : test::CubePrint {
    RaftPrint()
        : CubePrint({{"adhesion_type", "raft"},
                     {"raft_surface_layers", "2"},
                     {"raft_base_fan_speed", "0"},
                     {"raft_interface_fan_speed", "50"},
                     {"raft_surface_fan_speed", "100"},
                     {"raft_margin", "5"},
                     {"cool_min_layer_time", "0"},
                     {"cool_fan_full_layer", "3"},
                     {"retraction_combing", "all"}}) {
        PlannerState state;
        plan = planPrint(toolpaths, machine.global, machine.extruders, state);
    }
    PrintPlan plan;
};

std::vector<PlanStep> stepsOf(const PlannedLayer& layer, PlanStep::Kind kind) {
    std::vector<PlanStep> out;
    for (const PlanStep& s : layer.steps) {
        if (s.kind == kind)
            out.push_back(s);
    }
    return out;
}

TEST(RaftPlan, RaftLayersFirstWithTheirNumbersThicknessAndFan) {
    const RaftPrint r;
    ASSERT_EQ(r.toolpaths.raft.size(), 4U);  // no support: no filler layers printed
    ASSERT_EQ(r.plan.layers.size(), 4U + 20U);
    const RaftLayout layout = raftLayout(r.machine.global, &r.machine.extruders);
    const std::vector<int> raft_indexes{r.plan.layers[0].index, r.plan.layers[1].index,
                                        r.plan.layers[2].index, r.plan.layers[3].index};
    const int base = -layout.extraLayerCount();
    EXPECT_EQ(raft_indexes, (std::vector<int>{base, base + 1, base + 2, base + 3}));
    EXPECT_EQ(r.plan.layers[4].index, 0);
    EXPECT_EQ(r.plan.layers[0].thickness, layout.base_thickness_um);
    EXPECT_EQ(r.plan.layers[0].z, layout.base_thickness_um);
    EXPECT_EQ(r.plan.layers[3].z, layout.totalThicknessUm());
    EXPECT_EQ(r.plan.layers[4].z, r.stack.heights[0].print_z + layout.modelLiftUm(0));
    EXPECT_EQ(r.plan.layers[4].thickness, r.stack.heights[0].print_z);
    const double fans[] = {0.0, 0.5, 1.0, 1.0};
    for (int i = 0; i < 4; ++i) {
        const PlannedLayer& layer = r.plan.layers[static_cast<std::size_t>(i)];
        EXPECT_DOUBLE_EQ(stepsOf(layer, PlanStep::Kind::SetFan).at(0).fan_ratio, fans[i]) << i;
        EXPECT_TRUE(stepsOf(layer, PlanStep::Kind::SetMesh).empty()) << i;  // no ;MESH: on the raft
    }
    // The model's layer 0 ramps its fan from cool_fan_speed_0 as without a raft.
    EXPECT_DOUBLE_EQ(stepsOf(r.plan.layers[4], PlanStep::Kind::SetFan).at(0).fan_ratio, 0.0);
}

TEST(RaftPlan, BaseLoopBeforeItsLinesAndVolumesOfTheRaftsThickness) {
    const RaftPrint r;
    const PlannedLayer& base = r.plan.layers[0];
    const std::vector<PlanStep> features = stepsOf(base, PlanStep::Kind::SetFeature);
    ASSERT_EQ(features.size(), 1U);
    EXPECT_EQ(features[0].feature, Feature::RaftBase);
    // The loop first (0.4 mm inside the raft's outline), then the lines.
    const std::vector<PlanStep> moves = stepsOf(base, PlanStep::Kind::Extrude);
    const ExtrusionPath& loop = r.toolpaths.raft[0].paths.front();
    ASSERT_TRUE(loop.closed);
    ASSERT_GT(moves.size(), loop.points.size());
    for (std::size_t i = 0; i < loop.points.size(); ++i)
        EXPECT_NE(std::find(loop.points.begin(), loop.points.end(), moves[i].to), loop.points.end()) << i;
    const coord_um w = r.machine.global.lengthMicrons(key::raft_base_line_width);
    // Volume: length × raft_base_line_width × raft_base_thickness.
    const std::vector<PlanStep> travels = stepsOf(base, PlanStep::Kind::Travel);
    double volume = 0;
    for (const PlanStep& s : moves)
        volume += s.volume_mm3;
    double length_mm = 0;
    Point2 head = r.plan.layers[0].steps.front().to;
    bool started = false;
    for (const PlanStep& s : base.steps) {
        if (s.kind == PlanStep::Kind::Extrude && started)
            length_mm += std::hypot(double(s.to.X - head.X), double(s.to.Y - head.Y)) / 1000.0;
        if (s.kind == PlanStep::Kind::Travel || s.kind == PlanStep::Kind::Extrude) {
            head = s.to;
            started = true;
        }
    }
    EXPECT_NEAR(volume, length_mm * micronsToMm(w) * micronsToMm(r.plan.layers[0].thickness), 1e-6 * volume);
    // Travel between the lines combs inside the raft: no retraction there.
    std::size_t retracted = 0;
    for (const PlanStep& s : travels)
        retracted += s.retract ? 1 : 0;
    EXPECT_LE(retracted, 1U);  // at most the first move onto the raft
}

}  // namespace
}  // namespace mixengine
