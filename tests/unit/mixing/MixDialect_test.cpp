// The mixing dialects (gcode/mixdialect/MixDialect.h, MixTotalAxis, MixSplitAxes, MixChannelSplit): exact
// text of short sequences, and the invariant that a move's channel amounts add up exactly to the
// single-colour E word, in absolute and relative mode.
#include "gcode/mixdialect/MixDialect.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <sstream>

#include "gcode/format/ExtrusionAxis.h"
#include "gcode/mixdialect/MixChannelSplit.h"

namespace mixengine {
namespace {

MixVector mixB(double b) {
    MixVector m = MixVector::only(0, 2);
    m[0] = 1.0 - b;
    m[1] = b;
    return m;
}

MixingOutput mixing(MixDialectKind kind, int channels = 2) {
    MixingOutput m;
    m.mode = MixingMode::Gradient;
    m.dialect = kind;
    m.channels = channels;
    return m;
}

/// Runs a fixed sequence through a dialect; one line per call, "before" lines first.
std::string script(MixDialect& d) {
    std::string out, before;
    auto emit = [&](const std::string& words) {
        out += before + words + "\n";
        before.clear();
    };
    emit(d.extrude(1.0, mixB(0.25), before));
    emit(d.extrude(2.0, mixB(0.25), before));
    emit(d.retract(1.0, before));
    emit(d.prime(1.0, before));
    emit(d.extrude(1.0, mixB(0.5), before));
    out += d.reset() + "\n";
    emit(d.extrude(0.5, mixB(0.5), before));
    return out;
}

TEST(MixingDialect, SingleModeIsTheSingleColourAxis) {
    auto d = makeMixDialect(MixingOutput{}, false);
    EXPECT_EQ(script(*d), "E1\nE3\nE2\nE3\nE4\nG92 E0\nE0.5\n");
    EXPECT_EQ(d->channelTotals(), std::vector<double>{4.5});
}

TEST(MixingDialect, EbAxesAbsoluteResetBoth) {
    auto d = makeMixDialect(mixing(MixDialectKind::EbAxes), false);
    EXPECT_EQ(script(*d),
              "G92 B0 ;MIXING: filament A on E, B on B (M82/M83 and G92 act on both)\n"
              "E0.75 B0.25\nE2.25 B0.75\nE1.5 B0.5\nE2.25 B0.75\nE2.75 B1.25\nG92 E0 B0\nE0.25 B0.25\n");
    EXPECT_EQ(d->channelTotals(), (std::vector<double>{3.0, 1.5}));
    EXPECT_DOUBLE_EQ(d->totalExtruded(), 4.5);
}

TEST(MixingDialect, EbAxesRelative) {
    auto d = makeMixDialect(mixing(MixDialectKind::EbAxes), true);
    EXPECT_EQ(script(*d), "E0.75 B0.25\nE1.5 B0.5\nE-0.75 B-0.25\nE0.75 B0.25\nE0.5 B0.5\n\nE0.25 B0.25\n");
}

TEST(MixingDialect, KlipperKeepsBAbsoluteAndNeverResetsIt) {
    auto d = makeMixDialect(mixing(MixDialectKind::KlipperB), true);  // M83: E relative, B still absolute
    const std::string text = script(*d);
    EXPECT_EQ(
        text,
        ";MIXING: filament B on Klipper manual_stepper 'mixing_b' as axis B: absolute positions (G90) from "
        "0, never reset by G92\n"
        "MANUAL_STEPPER STEPPER=mixing_b GCODE_AXIS=\n"
        "MANUAL_STEPPER STEPPER=mixing_b SET_POSITION=0\n"
        "MANUAL_STEPPER STEPPER=mixing_b GCODE_AXIS=B\n"
        "G90\n"
        "E0.75 B0.25\nE1.5 B0.75\nE-0.75 B0.5\nE0.75 B0.75\nE0.5 B1.25\n\nE0.25 B1.5\n");
    auto absolute = makeMixDialect(mixing(MixDialectKind::KlipperB), false);
    std::string before;
    absolute->extrude(1.0, mixB(0.5), before);
    EXPECT_EQ(absolute->reset(), "G92 E0");  // only E: G92 cannot touch the manual_stepper axis
    EXPECT_EQ(absolute->extrude(1.0, mixB(0.5), before), "E0.5 B1");
}

TEST(MixingDialect, ReprapColonIsAlwaysRelative) {
    auto d = makeMixDialect(mixing(MixDialectKind::RrfColon), false);
    EXPECT_EQ(script(*d),
              "M83 ;relative extrusion mode (forced: RepRapFirmware accepts E a:b only with M83)\n"
              "E0.75:0.25\nE1.5:0.5\nE-0.75:-0.25\nE0.75:0.25\nE0.5:0.5\n\nE0.25:0.25\n");
    auto relative = makeMixDialect(mixing(MixDialectKind::RrfColon, 3), true);
    std::string before;
    MixVector thirds = MixVector::only(0, 3);
    thirds[0] = 0.5;
    thirds[2] = 0.5;
    EXPECT_EQ(relative->extrude(1.0, thirds, before), "E0.5:0:0.5");
    EXPECT_EQ(before,
              ";MIXING: E a:b words; RepRapFirmware accepts them only in relative extrusion mode (M83)\n");
}

TEST(MixingDialect, MixCommandsOnlyWhenTheQuantisedMixChanges) {
    auto m163 = makeMixDialect(mixing(MixDialectKind::MarlinM163), false);
    std::string before;
    EXPECT_EQ(m163->extrude(1.0, mixB(0.251), before), "E1");
    EXPECT_EQ(before, "M163 S0 P0.75\nM163 S1 P0.25\nM164 S0\nT0\n");
    before.clear();
    EXPECT_EQ(m163->extrude(1.0, mixB(0.254), before), "E2");  // still 25 % at 1 % resolution
    EXPECT_EQ(before, "");
    EXPECT_EQ(m163->extrude(1.0, mixB(0.256), before), "E3");
    EXPECT_EQ(before, "M163 S0 P0.74\nM163 S1 P0.26\nM164 S0\n");  // T only the first time

    MixingOutput m165 = mixing(MixDialectKind::MarlinM165, 5);
    auto d165 = makeMixDialect(m165, true);
    before.clear();
    MixVector five = MixVector::only(4, 5);
    EXPECT_EQ(d165->extrude(0.5, five, before), "E0.5");
    EXPECT_EQ(before, "M165 A0 B0 C0 D0 H1\n");

    MixingOutput m567 = mixing(MixDialectKind::RrfM567);
    m567.tool = 2;
    m567.resolution_steps = 8;
    auto d567 = makeMixDialect(m567, true);
    before.clear();
    d567->extrude(1.0, mixB(0.3), before);
    EXPECT_EQ(before, "M567 P2 E0.75:0.25\n");  // 0.3 → 2/8
}

/// The per-move amount a firmware sees on one axis between consecutive words.
struct Reader {
    bool relative;
    long long last = 0;
    long long step(long long written) {
        const long long moved = relative ? written : written - last;
        last = written;
        return moved;
    }
};

long long unitsOf(const std::string& number) {
    return std::llround(std::stod(number) * 1e5);
}

TEST(MixingDialect, ChannelsAddUpToTheSingleColourWordOnEveryMove) {
    for (bool relative : {false, true}) {
        ExtrusionAxis single('E', relative);
        auto eb = makeMixDialect(mixing(MixDialectKind::EbAxes), relative);
        Reader single_reader{relative}, e_reader{relative}, b_reader{relative};
        std::string before;
        for (int i = 0; i < 5000; ++i) {
            const double amount = 0.001 + 0.37 * std::fmod(i * 0.61803398875, 1.0);
            const MixVector mix = mixB(std::fmod(i * 0.1234567, 1.0));
            const std::string words = eb->extrude(amount, mix, before);
            const long long total = single_reader.step(unitsOf(single.move(amount).substr(1)));
            std::istringstream in(words);
            std::string e, b;
            in >> e >> b;
            const long long sum = e_reader.step(unitsOf(e.substr(1))) + b_reader.step(unitsOf(b.substr(1)));
            ASSERT_EQ(sum, total) << "move " << i << " relative " << relative << ": " << words;
            if (i % 700 == 699) {
                EXPECT_EQ(eb->reset(), single.reset().empty() ? "" : "G92 E0 B0");
                single_reader.last = e_reader.last = b_reader.last = 0;
            }
        }
    }
}

TEST(MixingDialect, AxisUnitsAreWhatTheFirmwareSeesBetweenWords) {
    ExtrusionAxis absolute('E', false), relative('E', true);
    EXPECT_EQ(absolute.moveUnits(0.123456), 12346);  // written E0.12346
    EXPECT_EQ(absolute.moveUnits(0.123456), 12345);  // written E0.24691
    EXPECT_EQ(absolute.moveUnits(-1.0), -100000);
    EXPECT_EQ(absolute.reset(), "G92 E0");
    EXPECT_EQ(absolute.moveUnits(0.000004), 0);  // E0
    EXPECT_EQ(relative.moveUnits(0.123456), 12346);
    EXPECT_EQ(relative.moveUnits(0.123456), 12345);
    EXPECT_DOUBLE_EQ(relative.totalExtruded(), 0.246912);
    EXPECT_EQ(formatUnits(-12345), "-0.12345");
}

TEST(MixingChannelSplit, WholeUnitsNeverNegativeAndCarried) {
    MixChannelSplit split;
    MixVector mix = MixVector::only(0, 3);
    mix[0] = 0.2;
    mix[1] = 0.3;
    mix[2] = 0.5;
    std::array<long long, 3> sums{};
    long long total = 0;
    for (int i = 0; i < 1000; ++i) {
        const long long units = 1 + (i * 7919) % 13;  // small moves: rounding matters
        const ChannelUnits parts = split.split(units, mix);
        EXPECT_EQ(std::accumulate(parts.begin(), parts.end(), 0LL), units);
        for (int c = 0; c < 3; ++c) {
            EXPECT_GE(parts[static_cast<std::size_t>(c)], 0);
            sums[static_cast<std::size_t>(c)] += parts[static_cast<std::size_t>(c)];
        }
        EXPECT_EQ(parts[3] + parts[4], 0);
        total += units;
    }
    // Error diffusion: each channel's total is within one unit of its exact share.
    for (int c = 0; c < 3; ++c)
        EXPECT_LE(std::abs(static_cast<double>(sums[static_cast<std::size_t>(c)]) - total * mix[c]), 1.0)
            << c;
    // A zero-share channel gets nothing, also right after a mix change.
    const ChannelUnits only_b = split.split(7, MixVector::only(1, 3));
    EXPECT_EQ(only_b[0], 0);
    EXPECT_EQ(only_b[1], 7);
    // Retractions are mirrored.
    const ChannelUnits back = split.split(-10, mix, false);
    EXPECT_EQ(back[0] + back[1] + back[2], -10);
    EXPECT_LE(back[0], 0);
}

}  // namespace
}  // namespace mixengine
