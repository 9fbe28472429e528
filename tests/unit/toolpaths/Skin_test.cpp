// Top/bottom skin areas (toolpaths/Skin.h) on stacks of squares.
#include "toolpaths/Skin.h"

#include <gtest/gtest.h>

namespace mixengine {
namespace {

Paths square(coord_um x0, coord_um y0, coord_um size) {
    return {{{x0, y0}, {x0 + size, y0}, {x0 + size, y0 + size}, {x0, y0 + size}}};
}

double areaOf(const Paths& paths) {
    double total = 0;
    for (const Path& p : paths)
        total += ClipperLib::Area(p);
    return total;
}

TEST(Skin, StackOfIdenticalSquares) {
    const std::vector<Paths> areas(6, square(0, 0, 10'000));
    for (int threads : {1, 2}) {
        const std::vector<Paths> skin = computeSkinAreas(areas, 2, 2, threads);
        ASSERT_EQ(skin.size(), 6U);
        for (int layer : {0, 1, 4, 5})
            EXPECT_EQ(areaOf(skin[layer]), 100e6) << layer << " threads " << threads;
        EXPECT_TRUE(skin[2].empty()) << threads;
        EXPECT_TRUE(skin[3].empty()) << threads;
    }
}

TEST(Skin, NoTopOrBottomLayersNoSkin) {
    const std::vector<Paths> areas(4, square(0, 0, 10'000));
    for (const Paths& skin : computeSkinAreas(areas, 0, 0, 1))
        EXPECT_TRUE(skin.empty());
    const std::vector<Paths> only_top = computeSkinAreas(areas, 1, 0, 1);
    EXPECT_TRUE(only_top[0].empty());
    EXPECT_EQ(areaOf(only_top[3]), 100e6);
}

TEST(Skin, SmallerSquareOnTopLeavesARing) {
    std::vector<Paths> areas(3, square(0, 0, 20'000));
    for (int i = 0; i < 3; ++i)
        areas.push_back(square(5'000, 5'000, 10'000));
    const std::vector<Paths> skin = computeSkinAreas(areas, 1, 1, 1);
    EXPECT_EQ(areaOf(skin[0]), 400e6);  // bottom layer
    EXPECT_TRUE(skin[1].empty());
    EXPECT_EQ(areaOf(skin[2]), 400e6 - 100e6);  // the ring not covered by the small square above
    EXPECT_TRUE(skin[3].empty());               // fully supported by the big square below
    EXPECT_TRUE(skin[4].empty());
    EXPECT_EQ(areaOf(skin[5]), 100e6);  // top layer
}

TEST(Skin, EmptyLayerInTheMiddle) {
    const std::vector<Paths> areas{
        square(0, 0, 10'000), square(0, 0, 10'000), {}, square(0, 0, 10'000), square(0, 0, 10'000)};
    const std::vector<Paths> skin = computeSkinAreas(areas, 1, 1, 2);
    EXPECT_EQ(areaOf(skin[0]), 100e6);
    EXPECT_EQ(areaOf(skin[1]), 100e6);
    EXPECT_TRUE(skin[2].empty());
    EXPECT_EQ(areaOf(skin[3]), 100e6);
    EXPECT_EQ(areaOf(skin[4]), 100e6);
}

TEST(Skin, BooleanHelpers) {
    const Paths a = square(0, 0, 10'000);
    const Paths b = square(5'000, 0, 10'000);
    EXPECT_EQ(areaOf(intersectAll(a, b)), 50e6);
    EXPECT_EQ(areaOf(differenceOf(a, b)), 50e6);
    EXPECT_TRUE(intersectAll(a, {}).empty());
    EXPECT_EQ(areaOf(differenceOf(a, {})), 100e6);
}

}  // namespace
}  // namespace mixengine
