// The extrusion axis bookkeeping (gcode/format/ExtrusionAxis.h): absolute (M82) and relative (M83) words,
// resets and the filament total.
#include "gcode/format/ExtrusionAxis.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace mixengine {
namespace {

/// The value of a word such as "E12.34567", in units of 1e-5 mm (the written resolution).
long long wordUnits(const std::string& word, char letter = 'E') {
    EXPECT_EQ(word.front(), letter) << word;
    return std::llround(std::stod(word.substr(1)) * 1e5);
}

TEST(ExtrusionAxis, AbsoluteWordsCarryThePosition) {
    ExtrusionAxis axis('E', false);
    EXPECT_FALSE(axis.relative());
    EXPECT_FALSE(axis.resetNeeded());
    EXPECT_EQ(axis.move(1.0), "E1");
    EXPECT_EQ(axis.move(0.5), "E1.5");
    EXPECT_EQ(axis.move(-6.5), "E-5");
    EXPECT_EQ(axis.move(6.5), "E1.5");
    EXPECT_EQ(axis.move(0.25), "E1.75");
    EXPECT_EQ(axis.position(), 1.75);
    EXPECT_EQ(axis.totalExtruded(), 1.75);
    EXPECT_TRUE(axis.resetNeeded());
    EXPECT_EQ(axis.reset(), "G92 E0");
    EXPECT_EQ(axis.position(), 0.0);
    EXPECT_FALSE(axis.resetNeeded());
    EXPECT_EQ(axis.move(0.1), "E0.1");
    EXPECT_DOUBLE_EQ(axis.totalExtruded(), 1.85);
}

TEST(ExtrusionAxis, RelativeWordsCarryTheDelta) {
    ExtrusionAxis axis('E', true);
    EXPECT_TRUE(axis.relative());
    EXPECT_EQ(axis.move(1.0), "E1");
    EXPECT_EQ(axis.move(0.5), "E0.5");
    EXPECT_EQ(axis.move(-6.5), "E-6.5");
    EXPECT_EQ(axis.move(6.5), "E6.5");
    EXPECT_EQ(axis.move(0.25), "E0.25");
    EXPECT_EQ(axis.totalExtruded(), 1.75);
    EXPECT_FALSE(axis.resetNeeded());
    EXPECT_EQ(axis.reset(), "");
    EXPECT_EQ(axis.move(0.1), "E0.1");
}

TEST(ExtrusionAxis, RelativeWordsSumToTheAbsoluteFinalValue) {
    const std::vector<double> deltas{0.123456,  0.234567,  0.000004,    0.000004, 0.000004, -6.5,     6.5,
                                     1.0 / 3.0, 0.0000049, 2.718281828, 0.000001, 0.000006, -1.0,     1.0,
                                     0.0314159, 0.0000001, 0.1,         0.2,      0.3,      0.7777777};
    ExtrusionAxis absolute('E', false);
    ExtrusionAxis relative('E', true);
    std::string last_absolute;
    long long relative_sum = 0;
    for (double delta : deltas) {
        last_absolute = absolute.move(delta);
        relative_sum += wordUnits(relative.move(delta));
    }
    EXPECT_EQ(relative_sum, wordUnits(last_absolute)) << last_absolute;
    EXPECT_DOUBLE_EQ(absolute.totalExtruded(), relative.totalExtruded());
}

TEST(ExtrusionAxis, TotalExcludesRetractionsAndPrimes) {
    ExtrusionAxis axis('E', false);
    axis.move(5.0);
    axis.move(-2.0);  // retract
    axis.move(1.0);   // partial prime: no new filament
    EXPECT_EQ(axis.totalExtruded(), 5.0);
    axis.move(3.0);  // 1 mm prime + 2 mm new
    EXPECT_EQ(axis.totalExtruded(), 7.0);
    axis.move(-1.0);
    axis.move(-1.0);
    axis.move(2.0);
    EXPECT_EQ(axis.totalExtruded(), 7.0);
    EXPECT_EQ(axis.position(), 7.0);
}

TEST(ExtrusionAxis, OtherLetter) {
    ExtrusionAxis axis('B', false);
    EXPECT_EQ(axis.letter(), 'B');
    EXPECT_EQ(axis.move(2.5), "B2.5");
    EXPECT_EQ(axis.reset(), "G92 B0");
}

}  // namespace
}  // namespace mixengine
