// Compact G-code number formatting (gcode/format/NumberFormat.h): fixed decimals, trailing zeros and point
// removed, never "-0".
#include "gcode/format/NumberFormat.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <string>

namespace mixengine {
namespace {

TEST(NumberFormat, CoordinatesThreeDecimals) {
    EXPECT_EQ(formatCoordMm(-0.0001), "0");
    EXPECT_EQ(formatCoordMm(-0.0), "0");
    EXPECT_EQ(formatCoordMm(0.0), "0");
    EXPECT_EQ(formatCoordMm(1.23456), "1.235");
    EXPECT_EQ(formatCoordMm(10.0), "10");
    EXPECT_EQ(formatCoordMm(100.0), "100");
    EXPECT_EQ(formatCoordMm(111.353), "111.353");
    EXPECT_EQ(formatCoordMm(110.5), "110.5");
    EXPECT_EQ(formatCoordMm(-1.5), "-1.5");
    EXPECT_EQ(formatCoordMm(-0.0004), "0");
    EXPECT_EQ(formatCoordMm(-0.0006), "-0.001");
    EXPECT_EQ(formatCoordMm(0.3), "0.3");
    EXPECT_EQ(formatCoordMm(1234567.891), "1234567.891");
}

TEST(NumberFormat, ExtrusionFiveDecimals) {
    EXPECT_EQ(formatExtrusion(0.000004), "0");
    EXPECT_EQ(formatExtrusion(-0.000004), "0");
    EXPECT_EQ(formatExtrusion(1.234567), "1.23457");
    EXPECT_EQ(formatExtrusion(0.03799), "0.03799");
    EXPECT_EQ(formatExtrusion(354.926), "354.926");
    EXPECT_EQ(formatExtrusion(-6.5), "-6.5");
    EXPECT_EQ(formatExtrusion(15.0), "15");
    EXPECT_EQ(formatExtrusion(0.000006), "0.00001");
}

TEST(NumberFormat, FeedrateInMmPerMinute) {
    EXPECT_EQ(formatFeedrate(25), "1500");
    EXPECT_EQ(formatFeedrate(28.125), "1687.5");
    EXPECT_EQ(formatFeedrate(30), "1800");
    EXPECT_EQ(formatFeedrate(120), "7200");
    EXPECT_EQ(formatFeedrate(0.5), "30");
    EXPECT_EQ(formatFeedrate(33.33333), "2000");
    EXPECT_EQ(formatFeedrate(1.0 / 60.0), "1");
}

TEST(NumberFormat, DecimalsZeroKeepsIntegerZeros) {
    EXPECT_EQ(formatDecimal(1000.0, 0), "1000");
    EXPECT_EQ(formatDecimal(-0.4, 0), "0");
    EXPECT_EQ(formatDecimal(60.0, 1), "60");
}

// CuraEngine 4.13 writes F, E, M106 and M204 values with printf's "%.<n>f", which rounds the exact
// binary value, ties to even: 2.5 → "2", 1.25 → "1.2", and 2.55 (stored as 2.5499…) → "2.5" (1 % fan).
TEST(NumberFormat, RoundsAsPrintfDoes) {
    EXPECT_EQ(formatDecimal(2.5, 0), "2");
    EXPECT_EQ(formatDecimal(-2.5, 0), "-2");
    EXPECT_EQ(formatDecimal(3.5, 0), "4");
    EXPECT_EQ(formatDecimal(1.25, 1), "1.2");
    EXPECT_EQ(formatDecimal(1.0 * 255 / 100, 1), "2.5");
    EXPECT_EQ(formatDecimal(0.15, 1), "0.1");  // 0.1499…
    EXPECT_EQ(formatDecimal(0.35, 1), "0.3");  // 0.3499…
}

/// printf's "%.*f" text of `value`, trailing zeros and point removed, "-0" as "0": the oracle.
std::string printfText(double value, int decimals) {
    char buffer[128];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
    std::string text(buffer);
    if (decimals > 0) {
        while (text.back() == '0')
            text.pop_back();
        if (text.back() == '.')
            text.pop_back();
    }
    return text == "-0" ? "0" : text;
}

// The integer path must write what printf writes for every value G-code carries: coordinates, feedrates,
// E values, and values on and next to the .5 ties of each number of decimals.
TEST(NumberFormat, MatchesPrintfOnManyValues) {
    std::mt19937_64 random(20261205);
    std::uniform_real_distribution<double> spread(-5000.0, 5000.0);
    std::uniform_int_distribution<int> digits(0, 8);
    for (int i = 0; i < 200000; ++i) {
        const int decimals = digits(random);
        double value = spread(random);
        if (i % 4 == 1)  // a tie, or the double next to it
            value = (std::round(value * 1000.0) + 0.5) / 1000.0;
        if (i % 4 == 2)
            value = std::nextafter((std::round(value * 10.0) + 0.5) / 10.0, 0.0);
        if (i % 4 == 3)
            value /= 1e6;
        ASSERT_EQ(formatDecimal(value, decimals), printfText(value, decimals)) << value << " " << decimals;
    }
}

TEST(NumberFormat, MicronsAreWrittenAsPrintfWritesTheirMillimetres) {
    const auto microns = [](std::int64_t um) {
        std::string text;
        appendMicronsAsMm(text, um);
        return text;
    };
    EXPECT_EQ(microns(0), "0");
    EXPECT_EQ(microns(108777), "108.777");
    EXPECT_EQ(microns(110500), "110.5");
    EXPECT_EQ(microns(-1), "-0.001");
    EXPECT_EQ(microns(-250000), "-250");
    EXPECT_EQ(microns(7), "0.007");
    std::mt19937_64 random(20261206);
    std::uniform_int_distribution<std::int64_t> spread(-2'000'000'000, 2'000'000'000);
    for (int i = 0; i < 100000; ++i) {
        const std::int64_t um = i % 2 == 0 ? spread(random) : spread(random) % 1000;
        ASSERT_EQ(microns(um), printfText(static_cast<double>(um) / 1000.0, 3)) << um;
    }
}

}  // namespace
}  // namespace mixengine
