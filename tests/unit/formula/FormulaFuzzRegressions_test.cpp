// Inputs found by the libFuzzer targets (tests/fuzz), kept as regression tests.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "common/Error.h"
#include "settings/TypedText.h"
#include "unit/formula/FormulaTestSupport.h"

namespace mixengine::formula::test {
namespace {

// formula_fuzz: "100. if cool 0._0" — the lexer scanned "0._0" as a float literal and parseFloatString's
// internal EvalProblem escaped parse() (a std::terminate in the fuzzer, "internal error" exit 2 in the CLI).
TEST(FormulaFuzzRegressions, MisplacedUnderscoreInFloatLiteralIsAFormulaError) {
    for (const std::string formula : {"0._0", "100. if cool 0._0", "1._5e3", "[0._0, 1]"}) {
        try {
            parse(formula);
            ADD_FAILURE() << "no error for " << formula;
        } catch (const FormulaError& e) {
            EXPECT_NE(std::string(e.what()).find("invalid decimal literal"), std::string::npos) << e.what();
        }
    }
}

// settings_fuzz: a setting value holding a polygon literal with "0._0" left Cura's -s parsing as an
// internal error; it is an InputError naming the setting.
TEST(FormulaFuzzRegressions, PolygonSettingWithBadLiteralIsAnInputError) {
    try {
        valueFromText("machine_disallowed_areas", "polygons", "[[[0._0, 1], [1, 1], [1, 0]]]");
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("machine_disallowed_areas"), std::string::npos) << e.what();
    }
}

// settings_fuzz: "2e4444...4" (an exponent beyond LONG_MAX) overflowed a long in literalOverflows (UBSan),
// and the wrapped sum classified the literal as tiny: 0.0 instead of Python's inf.
TEST(FormulaFuzzRegressions, HugeExponentLiteralsAreInfinityOrZeroAsInPython) {
    const std::string fours(60, '4');
    EXPECT_EQ(repr("2e" + fours), "inf");
    EXPECT_EQ(repr("-2e" + fours), "-inf");
    EXPECT_EQ(repr("2e-" + fours), "0.0");
    EXPECT_EQ(repr("float('7e9223372036854775808')"), "inf");
}

}  // namespace
}  // namespace mixengine::formula::test
