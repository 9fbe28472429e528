// Stair-stepped support on slopes (toolpaths/support/SupportStairs.h) on a 45° slope.
#include "toolpaths/support/SupportStairs.h"

#include <gtest/gtest.h>

#include "ToolpathTestSupport.h"
#include "geometry/PolygonOps.h"

namespace mixengine {
namespace {

using test::rect;

/// 20 layers of 0.2 mm, each 0.2 mm shorter in x than the one below: a 45° slope facing +x.
std::vector<Paths> slope() {
    std::vector<Paths> model;
    for (coord_um i = 0; i < 20; ++i)
        model.push_back({rect(0, 0, 10'000 - 200 * i, 10'000)});
    return model;
}

TEST(SupportStairs, WithoutStepsOnlyTheModelBottomGapLayersDownIsKeptFree) {
    const std::vector<Paths> model = slope();
    const StairParams p{1, 5'000, 10, 1};
    const std::vector<Paths> sloped = slopedAreas(model, p, 200, 1);
    StairSteps stairs(&model, &sloped, p);
    for (std::size_t i = model.size(); i-- > 0;) {
        const Paths free = stairs.keptFree(i);
        EXPECT_EQ(areaUm2(free), i == 0 ? 0.0 : areaUm2(model[i - 1])) << i;
    }
}

TEST(SupportStairs, StepsKeepTheStepsLowestLayerFreeOnTheSlope) {
    const std::vector<Paths> model = slope();
    const StairParams p{3, 5'000, 10, 1};
    const std::vector<Paths> sloped = slopedAreas(model, p, 200, 1);
    EXPECT_TRUE(sloped[0].empty());
    EXPECT_FALSE(sloped[5].empty());  // the receding edge is a slope
    StairSteps stairs(&model, &sloped, p);
    int wider = 0;
    for (std::size_t i = model.size(); i-- > 1;) {
        const double free = areaUm2(stairs.keptFree(i));
        EXPECT_GE(free, areaUm2(model[i - 1])) << i;
        wider += free > areaUm2(model[i - 1]) ? 1 : 0;
    }
    EXPECT_GE(wider, 4);  // the layer under each step leaves the step's lowest layer free
}

}  // namespace
}  // namespace mixengine
