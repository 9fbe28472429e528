// Commands that lead the chamber (mixing/transition/LeadCommands.h): its forward pass against the chamber
// model push by push, and the solution against what a field asks for.
#include "mixing/transition/LeadCommands.h"

#include <gtest/gtest.h>

#include <cmath>

namespace mixengine {
namespace {

MixVector shareB(double b) {
    MixVector m = MixVector::only(0, 2);
    m[0] = 1.0 - b;
    m[1] = b;
    return m;
}

TEST(MixingLeadCommands, OutletsAreTheChamberModelsPushByPush) {
    for (int stages : {1, 3, 7}) {
        const ChamberSpec spec{40, stages};
        std::vector<FlowCell> cells;
        std::vector<MixVector> commands;
        for (int k = 0; k < 60; ++k) {
            cells.push_back({0.3 + (k % 7) * 1.7, 0, {}});
            commands.push_back(shareB(0.5 + 0.5 * std::sin(k * 0.7)));
        }
        Chamber chamber(spec, shareB(0.2));
        const std::vector<MixVector> tanks(static_cast<std::size_t>(stages), shareB(0.2));
        const std::vector<MixVector> outlets = outletsOf(cells, tanks, commands, spec);
        for (std::size_t k = 0; k < cells.size(); ++k) {
            const MixVector left = chamber.push(commands[k], cells[k].volume_mm3);
            EXPECT_NEAR(outlets[k][1], left[1], 1e-12) << stages << " stages, cell " << k;
            EXPECT_NEAR(outlets[k][0], left[0], 1e-12);
        }
    }
}

/// A ramp of B from 0 to 1 over 300 mm³, asked on every other cell: commanded as asked, the outlet lags
/// the chamber's 40 mm³ behind (a 0.133 share); led, it follows within the margin.
TEST(MixingLeadCommands, ASlowRampIsFollowedOnceLed) {
    const ChamberSpec spec{40, 3};
    std::vector<FlowCell> cells;
    for (int k = 0; k < 400; ++k) {
        const double b = std::clamp((k - 50) / 300.0, 0.0, 1.0);
        cells.push_back({1.0, k % 2 == 0 ? 1.0 : 0.0, shareB(b)});
    }
    const std::vector<MixVector> tanks(3, shareB(0));
    std::vector<MixVector> as_asked;
    for (const FlowCell& c : cells)
        as_asked.push_back(c.asked);
    const std::vector<MixVector> lagging = outletsOf(cells, tanks, as_asked, spec);
    EXPECT_NEAR(cells[200].asked[1] - lagging[200][1], 40.0 / 300.0, 0.01);

    const LeadSettings settings{spec, 0.02, 400};
    const std::vector<MixVector> led =
        leadCommands(cells, tanks, leadingGuess(cells, 40, shareB(0)), settings);
    const std::vector<MixVector> outlets = outletsOf(cells, tanks, led, spec);
    double worst = 0;
    for (std::size_t k = 0; k < cells.size(); k += 2)
        worst = std::max(worst, std::abs(outlets[k][1] - cells[k].asked[1]));
    EXPECT_LT(worst, 0.03);
    EXPECT_GT(led[200][1], cells[200].asked[1] + 0.1);  // ahead of the ramp
    for (const MixVector& m : led) {
        EXPECT_GE(m[0], 0.0);
        EXPECT_GE(m[1], 0.0);
        EXPECT_NEAR(m[0] + m[1], 1.0, 1e-12);
    }
}

/// Three channels: the commands stay mixes (on the simplex) and the asked cells are met where the
/// chamber can follow.
TEST(MixingLeadCommands, CommandsStayMixesInThreeChannels) {
    const ChamberSpec spec{20, 3};
    std::vector<FlowCell> cells;
    for (int k = 0; k < 300; ++k) {
        MixVector m = MixVector::only(0, 3);
        const double t = std::clamp((k - 30) / 240.0, 0.0, 1.0);
        m[0] = 1 - t;
        m[2] = t;
        cells.push_back({1.0, k % 3 == 0 ? 1.0 : 0.0, m});
    }
    const std::vector<MixVector> tanks(3, MixVector::only(0, 3));
    const std::vector<MixVector> led =
        leadCommands(cells, tanks, leadingGuess(cells, 20, MixVector::only(0, 3)), {spec, 0.02, 400});
    const std::vector<MixVector> outlets = outletsOf(cells, tanks, led, spec);
    for (std::size_t k = 0; k < cells.size(); ++k) {
        EXPECT_NEAR(led[k].sum(), 1.0, 1e-12);
        for (int c = 0; c < 3; ++c)
            EXPECT_GE(led[k][c], 0.0);
        if (cells[k].weight > 0) {
            EXPECT_LT(shareDistance(outlets[k], cells[k].asked), 0.04) << k;
        }
    }
}

TEST(MixingLeadCommands, LeadingGuessLooksAheadAlongTheFlow) {
    std::vector<FlowCell> cells = {{5, 1, shareB(0.0)}, {5, 0, {}}, {5, 1, shareB(0.5)}, {5, 1, shareB(1.0)}};
    const std::vector<MixVector> guess = leadingGuess(cells, 7.5, shareB(0.3));
    EXPECT_DOUBLE_EQ(guess[0][1], 0.5);  // its middle 2.5 + 7.5 = 10: the third cell begins there
    EXPECT_DOUBLE_EQ(guess[1][1], 0.5);  // 7.5 + 7.5 = 15: the end of the third cell
    EXPECT_DOUBLE_EQ(guess[3][1], 1.0);  // beyond the end: the last asked
}

}  // namespace
}  // namespace mixengine
