// The --preview picture (mixing/Preview.h): mixed colours, the gradient from bottom to top, the
// nearest extrusion in front, and valid PNG bytes.
#include "mixing/Preview.h"

#include <gtest/gtest.h>

namespace mixengine {
namespace {

const std::vector<Rgb> kYellowPink = {Rgb{242, 197, 0}, Rgb{224, 64, 138}};

TEST(MixingPreview, MixedColoursInLinearLight) {
    EXPECT_EQ(mixColor(MixVector::only(0, 2), kYellowPink), kYellowPink[0]);
    EXPECT_EQ(mixColor(MixVector::only(1, 2), kYellowPink), kYellowPink[1]);
    MixVector half = MixVector::only(0, 2);
    half[0] = half[1] = 0.5;
    const Rgb black_white = mixColor(half, {Rgb{0, 0, 0}, Rgb{255, 255, 255}});
    EXPECT_EQ(black_white, (Rgb{188, 188, 188}));  // 50 % light is sRGB 188, not 128
}

PlanStep move(PlanStep::Kind kind, coord_um x, coord_um y, int mix) {
    PlanStep s;
    s.kind = kind;
    s.to = {x, y};
    s.volume_mm3 = 1;
    s.mix = mix;
    return s;
}

TEST(MixingPreview, BottomInAAndTopInBSeenFromTheFront) {
    PrintPlan plan;
    plan.mixes = {MixVector::only(0, 2), MixVector::only(1, 2), MixVector::only(0, 2)};
    for (int i = 0; i < 2; ++i) {
        PlannedLayer layer;
        layer.z = 5000 * (i + 1);
        // A line along X at the front (y = 0) in mix i, and one behind it (y = 10 mm) in mix 2.
        layer.steps.push_back(move(PlanStep::Kind::Travel, 0, 10000, -1));
        layer.steps.push_back(move(PlanStep::Kind::Extrude, 10000, 10000, 2));
        layer.steps.push_back(move(PlanStep::Kind::Travel, 0, 0, -1));
        layer.steps.push_back(move(PlanStep::Kind::Extrude, 10000, 0, i));
        plan.layers.push_back(layer);
    }
    SidePreview preview(kYellowPink, 120);
    preview.add(plan);
    const SidePreview::Image image = preview.render();
    ASSERT_EQ(image.width, 120);
    ASSERT_EQ(image.height, 120);
    const int middle = image.width / 2;
    EXPECT_EQ(image.at(middle, image.height - 20), kYellowPink[0]);  // lower layer, front line: A
    EXPECT_EQ(image.at(middle, 20), kYellowPink[1]);                 // upper layer, front line: B
    EXPECT_EQ(image.at(2, 2), (Rgb{230, 230, 230}));                 // margin: background
    const std::string png = preview.png();
    ASSERT_GT(png.size(), 8u);
    EXPECT_EQ(png.substr(1, 3), "PNG");
}

TEST(MixingPreview, NothingExtrudedGivesABlankPicture) {
    SidePreview preview(kYellowPink);
    const SidePreview::Image image = preview.render();
    EXPECT_GT(image.width, 0);
    EXPECT_EQ(image.at(0, 0), (Rgb{230, 230, 230}));
}

}  // namespace
}  // namespace mixengine
