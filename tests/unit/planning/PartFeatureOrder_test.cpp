// The order of a layer part's features (planning/PrintPlanner.h), as CuraEngine 4.13 prints a part
// (FffGcodeWriter::addMeshPartToGCode): walls, then infill, then skin — infill first of all with
// infill_before_walls.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "../toolpaths/ToolpathTestSupport.h"
#include "planning/PrintPlanner.h"

namespace mixengine {
namespace {

/// The features a layer's extrusions follow, each once, in the order they first appear.
std::vector<Feature> featureOrder(const PlannedLayer& layer) {
    std::vector<Feature> out;
    Feature feature = Feature::Fill;
    bool known = false;
    for (const PlanStep& s : layer.steps) {
        if (s.kind == PlanStep::Kind::SetFeature)
            feature = s.feature, known = true;
        if (s.kind == PlanStep::Kind::Extrude && known &&
            std::find(out.begin(), out.end(), feature) == out.end())
            out.push_back(feature);
    }
    return out;
}

/// A 20 mm square, 10 layers, under a 6 mm square of 10 more: the wide part's top layer has a ring of
/// top skin round the infill under the narrow part.
std::vector<Feature> stepTopOrder(const SettingValues& user) {
    const ResolvedMachine machine = test::fdmMachine(user);
    test::Stack stack = test::prismStack(20);
    test::fill(stack, 0, 10, {test::square(100'000, 100'000, 20'000)});
    test::fill(stack, 10, 20, {test::square(107'000, 107'000, 6'000)});
    const GroupToolpaths toolpaths = test::oneMeshToolpaths(machine, stack, "step");
    PlannerState state;
    const PrintPlan plan = planPrint(toolpaths, machine.global, machine.extruders, state);
    return featureOrder(plan.layers[9]);
}

TEST(PartFeatureOrder, WallsThenInfillThenSkin) {
    const std::vector<Feature> order = stepTopOrder(
        {{"adhesion_type", "none"}, {"infill_sparse_density", "20"}, {"infill_before_walls", "False"}});
    EXPECT_EQ(order,
              (std::vector<Feature>{Feature::WallInner, Feature::WallOuter, Feature::Fill, Feature::Skin}));
    const std::vector<Feature> infill_first = stepTopOrder(
        {{"adhesion_type", "none"}, {"infill_sparse_density", "20"}, {"infill_before_walls", "True"}});
    EXPECT_EQ(infill_first,
              (std::vector<Feature>{Feature::Fill, Feature::WallInner, Feature::WallOuter, Feature::Skin}));
}

}  // namespace
}  // namespace mixengine
