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

// Issue 29 item 4: values and formulas whose evaluation took unbounded memory or time. Each must end with
// the typed error (InputError / FormulaError) naming the key or formula and the limit, and nothing else.

// settings_fuzz (45 bytes: selector ';' = valueFromText as "polygon", then the text): list repetition
// nested in a repetition. Formula values are deep copies, so the outer `* 999999` copied the 2-million-item
// inner list 999999 times (2e12 items; out of memory). The per-repetition cap (2^24 items) counted only the
// outer list's 3 items.
TEST(FormulaFuzzRegressions, NestedRepetitionInAPolygonValueIsTooLarge) {
    const std::string value = "[[-20, 10]*999999, [10, 10], [0, -5]]*999999";
    try {
        valueFromText("fuzzed_setting", "polygon", value);
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(),
                     "setting 'fuzzed_setting': formula '[[-20, 10]*999999, [10, 10], [0, -5]]*999999': too "
                     "large (more than 1000000 elements: list items and string characters)");
    } catch (...) {
        ADD_FAILURE() << "an exception other than InputError";
    }
}

// Command line (issue 29 item 4 b): `-s machine_disallowed_areas=...` with this value took the engine to
// 18 GB in 60 s (67 million items: 186,600 deep copies of a 360-item list). Python shares the inner list.
TEST(FormulaFuzzRegressions, RepeatedListSettingValueIsTooLarge) {
    const std::string value = "[[0,0,[0,0,0,]]*120*1*1,0,[0,0,0,]]*120*1555";
    try {
        valueFromText("machine_disallowed_areas", "polygons", value);
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_STREQ(
            e.what(),
            "setting 'machine_disallowed_areas': formula '[[0,0,[0,0,0,]]*120*1*1,0,[0,0,0,]]*120*1555': "
            "too large (more than 1000000 elements: list items and string characters)");
    } catch (...) {
        ADD_FAILURE() << "an exception other than InputError";
    }
}

// formula_fuzz: nested comprehensions over a long string (4e8 iterations; more than 10 s per input). Each
// iteration copies its two 1-character strings, so the elements run out (at ~7 of the 20,000 outer
// iterations) before the steps.
TEST(FormulaFuzzRegressions, NestedComprehensionsOverALongStringAreBounded) {
    MapEnvironment env;
    env.settings["infill_pattern"] = Value("grid");
    const std::string formula =
        "[0 for a in infill_pattern * 5000 for b in infill_pattern * 5000 if a + b == '']";
    try {
        evaluate(parse(formula), env);
        ADD_FAILURE() << "no error";
    } catch (const FormulaError& e) {
        EXPECT_STREQ(e.what(),
                     "formula '[0 for a in infill_pattern * 5000 for b in infill_pattern * 5000 if a + b == "
                     "'']': too large (more than 1000000 elements: list items and string characters)");
    } catch (...) {
        ADD_FAILURE() << "an exception other than FormulaError";
    }
}

}  // namespace
}  // namespace mixengine::formula::test
