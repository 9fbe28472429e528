// The colour science of colour mode (mixing/color/ColorSpace.h, KubelkaMunk.h, ColorSolver.h):
// Little CMS's CIEDE2000 on Sharma's published pairs, known answers of the solver (a channel's
// own colour is 100 % of it, a predicted mix solves back to itself) and of the pigment model
// (yellow + blue is green, white lightens, black darkens).
#include "mixing/color/ColorSolver.h"

#include <gtest/gtest.h>

#include <cmath>

#include "common/Error.h"

namespace mixengine {
namespace {

Rgb hex(const char* text) {
    return parseHexColor("test", text);
}

MixVector mixOf(std::initializer_list<double> shares) {
    MixVector mix;
    mix.channels = static_cast<int>(shares.size());
    int c = 0;
    for (double s : shares)
        mix[c++] = s;
    return mix;
}

double hueDegrees(const Lab& lab) {
    const double h = std::atan2(lab.b, lab.a) * 180.0 / M_PI;
    return h < 0 ? h + 360.0 : h;
}

TEST(ColorSpace, CieDe2000OfSharmasTestPairs) {
    // G. Sharma, W. Wu, E. Dalal (2005), test data pairs 1, 7 and 17.
    EXPECT_NEAR(deltaE00({50.0, 2.6772, -79.7751}, {50.0, 0.0, -82.7485}), 2.0425, 1e-4);
    EXPECT_NEAR(deltaE00({50.0, 0.0, 0.0}, {50.0, -1.0, 2.0}), 2.3669, 1e-4);
    EXPECT_NEAR(deltaE00({50.0, 2.5, 0.0}, {73.0, 25.0, -18.0}), 27.1492, 1e-4);
}

TEST(ColorSpace, SrgbWhiteAndBlackInLab) {
    const ColorSpace space;
    const Lab white = space.labOf(hex("#ffffff"));
    EXPECT_NEAR(white.L, 100.0, 0.01);
    EXPECT_NEAR(white.a, 0.0, 0.01);
    EXPECT_NEAR(white.b, 0.0, 0.01);
    EXPECT_NEAR(space.labOf(hex("#000000")).L, 0.0, 0.01);
    EXPECT_EQ(space.srgbOf(space.labOf(hex("#ff8000"))), hex("#ff8000"));
}

TEST(ColorSpace, HexParsingAndItsError) {
    EXPECT_EQ(hex(" #FF8000 "), (Rgb{255, 128, 0}));
    EXPECT_EQ(hexOf(Rgb{255, 128, 0}), "#ff8000");
    try {
        parseHexColor("setting 'mixing_target_color'", "orange");
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "setting 'mixing_target_color': 'orange' is not a colour like #ff8800");
    }
}

TEST(PigmentModel, EveryChannelAloneIsItsOwnColour) {
    const std::vector<Rgb> colors{hex("#00ffff"), hex("#ff00ff"), hex("#ffff00"), hex("#ffffff"),
                                  hex("#000000")};
    const PigmentModel model(colors);
    for (int c = 0; c < 5; ++c)
        EXPECT_EQ(model.predictRgb(MixVector::only(c, 5)), colors[static_cast<std::size_t>(c)]) << c;
}

TEST(PigmentModel, YellowPlusBlueIsGreenNotGrey) {
    const PigmentModel model({hex("#ffff00"), hex("#0000ff")});
    const Lab mixed = model.predictLab(mixOf({0.5, 0.5}));
    const Rgb rgb = model.predictRgb(mixOf({0.5, 0.5}));
    EXPECT_GT(hueDegrees(mixed), 120.0);  // CIELAB green: hue between yellow (~100°) and cyan (~200°)
    EXPECT_LT(hueDegrees(mixed), 180.0);
    EXPECT_GT(std::hypot(mixed.a, mixed.b), 30.0);  // a saturated colour, not a grey
    EXPECT_GT(rgb[1], rgb[0]);
    EXPECT_GT(rgb[1], rgb[2]);
}

TEST(PigmentModel, WhiteLightensAndBlackDarkens) {
    const PigmentModel model({hex("#e0408a"), hex("#ffffff"), hex("#000000")});
    const double own = model.predictLab(mixOf({1, 0, 0})).L;
    EXPECT_GT(model.predictLab(mixOf({0.5, 0.5, 0})).L, own + 10);
    EXPECT_LT(model.predictLab(mixOf({0.5, 0, 0.5})).L, own - 10);
}

TEST(ColorSolver, TargetEqualToAChannelGivesAllOfThatChannel) {
    const std::vector<Rgb> colors{hex("#00ffff"), hex("#ff00ff"), hex("#ffff00"), hex("#ffffff"),
                                  hex("#262626")};
    const PigmentModel model(colors);
    for (int c = 0; c < 5; ++c) {
        const ColorSolution s = solveColor(model, colors[static_cast<std::size_t>(c)]);
        EXPECT_NEAR(s.mix[c], 1.0, 1e-9) << hexOf(colors[static_cast<std::size_t>(c)]);
        EXPECT_LT(s.delta_e00, 0.01);
        EXPECT_EQ(s.predicted_rgb, colors[static_cast<std::size_t>(c)]);
    }
}

TEST(ColorSolver, APredictedMixSolvesBackToThatMix) {
    const PigmentModel model({hex("#ffff00"), hex("#0000ff")});
    const ColorSolution half = solveColor(model, model.predictLab(mixOf({0.5, 0.5})));
    EXPECT_NEAR(half.mix[0], 0.5, 1e-4);
    EXPECT_NEAR(half.mix[1], 0.5, 1e-4);
    EXPECT_LT(half.delta_e00, 1e-3);
    // Through 8-bit sRGB (the target as a user writes it): within a percent.
    const ColorSolution rounded = solveColor(model, model.predictRgb(mixOf({0.5, 0.5})));
    EXPECT_NEAR(rounded.mix[0], 0.5, 0.01);
    const PigmentModel three({hex("#00ffff"), hex("#ff00ff"), hex("#ffff00")});
    const ColorSolution mixed = solveColor(three, three.predictLab(mixOf({0.2, 0.3, 0.5})));
    EXPECT_LT(mixed.delta_e00, 0.05);
    EXPECT_NEAR(mixed.mix[2], 0.5, 0.02);
}

TEST(ColorSolver, SharesAddUpToOne) {
    const PigmentModel model({hex("#00ffff"), hex("#ff00ff"), hex("#ffff00"), hex("#ffffff")});
    const ColorSolution s = solveColor(model, hex("#ff8000"));
    EXPECT_NEAR(s.mix.sum(), 1.0, 1e-9);
    EXPECT_EQ(s.mix.channels, 4);
}

}  // namespace
}  // namespace mixengine
