// Python semantics of every operator. Each case is a formula and the Python repr() of its result,
// which pins down the type as well as the value ("3" int, "3.0" float, "True" bool, "'3'" str).
#include <gtest/gtest.h>

#include "unit/formula/FormulaTestSupport.h"

namespace mixengine::formula::test {
namespace {

TEST(FormulaOperators, AdditionSubtractionMultiplication) {
    expectAll({
        {"1 + 2", "3"},
        {"1 + 2.0", "3.0"},
        {"True + True", "2"},
        {"7 - 10", "-3"},
        {"3 * 4", "12"},
        {"3 * 0.5", "1.5"},
        {"0.1 + 0.2", "0.30000000000000004"},
        {"3 - 1 - 1", "1"},
        {"2 * 3 + 4 * 5", "26"},
        {"(2 + 3) * 4", "20"},
        {"10 - 2 * 3 ** 2", "-8"},
        {"9223372036854775807 + 1", "9.223372036854776e+18"},  // beyond int64: continues as float
        {"299792458000 ** 2", "8.987551787368176e+22"},
    });
}

TEST(FormulaOperators, TrueDivisionAlwaysGivesFloat) {
    expectAll({
        {"7 / 2", "3.5"},
        {"6 / 3", "2.0"},
        {"1 / 3", "0.3333333333333333"},
        {"-1 / 4", "-0.25"},
        {"True / 2", "0.5"},
    });
}

TEST(FormulaOperators, FloorDivisionIsFloored) {
    expectAll({
        {"7 // 2", "3"},
        {"7 // -2", "-4"},
        {"-7 // 2", "-4"},
        {"-7 // -2", "3"},
        {"6 // 3", "2"},
        {"7.5 // 2", "3.0"},
        {"-7.5 // 2", "-4.0"},
        {"7 // 2.0", "3.0"},
        {"-0.5 // 1", "-1.0"},
        {"0.5 // -1", "-1.0"},
        {"1 // 0.3", "3.0"},
    });
}

TEST(FormulaOperators, ModuloTakesTheDivisorsSign) {
    expectAll({
        {"7 % 3", "1"},
        {"-7 % 3", "2"},
        {"7 % -3", "-2"},
        {"-7 % -3", "-1"},
        {"6 % -3", "0"},
        {"5.5 % 2", "1.5"},
        {"-5.5 % 2", "0.5"},
        {"5.5 % -2", "-0.5"},
        {"6.0 % -3", "-0.0"},
        {"-0.0 % 2", "0.0"},
        {"3 % 2", "1"},
        {"0.2 % 0.1", "0.0"},
        {"1.0 % 0.3", "0.10000000000000003"},
        {"-1.0 % 0.3", "0.19999999999999996"},
    });
}

TEST(FormulaOperators, Power) {
    expectAll({
        {"2 ** 10", "1024"},
        {"2 ** -1", "0.5"},
        {"2.0 ** 3", "8.0"},
        {"(-8) ** 3", "-512"},
        {"-2 ** 2", "-4"},
        {"2 ** 3 ** 2", "512"},
        {"4 ** 0.5", "2.0"},
        {"0 ** 0", "1"},
        {"(-2.0) ** 2", "4.0"},
        {"10 ** -2", "0.01"},
    });
}

TEST(FormulaOperators, Unary) {
    expectAll({
        {"-3", "-3"},
        {"+3.5", "3.5"},
        {"-True", "-1"},
        {"- -2", "2"},
        {"-(1 - 3)", "2"},
        {"not 0", "True"},
        {"not []", "True"},
        {"not 'a'", "False"},
        {"not 1 == 2", "True"},
        {"not not 5", "True"},
    });
}

TEST(FormulaOperators, StringAndListArithmetic) {
    expectAll({
        {"'ab' + 'cd'", "'abcd'"},
        {"'ab' * 3", "'ababab'"},
        {"2 * 'ab'", "'abab'"},
        {"'ab' * 0", "''"},
        {"'ab' * -1", "''"},
        {"'ab' * True", "'ab'"},
        {"[1, 2] + [3]", "[1, 2, 3]"},
        {"[0] * 3", "[0, 0, 0]"},
        {"[] + []", "[]"},
        {"'G1 X' + str(10) + ' Y' + str(2.5)", "'G1 X10 Y2.5'"},
    });
}

TEST(FormulaOperators, ChainedAndMixedTypeComparisons) {
    expectAll({
        {"1 < 2 < 3", "True"},
        {"1 < 3 < 2", "False"},
        {"3 > 2 > 1 > 0", "True"},
        {"1 < 2 == 2", "True"},
        {"1 <= 1 < 2 >= 2 != 3", "True"},
        {"1 == 1.0", "True"},
        {"1 == True", "True"},
        {"2 == True", "False"},
        {"0.1 + 0.2 == 0.3", "False"},
        {"1 != 1.0", "False"},
        {"2 >= 2.0", "True"},
        {"2 <= 1.9999999", "False"},
        {"9007199254740993 > 9007199254740992.0", "True"},
        {"9007199254740993 == 9007199254740992.0", "False"},
        {"None == None", "True"},
        {"None == 0", "False"},
        {"'1' == 1", "False"},
        {"'a' < 'b'", "True"},
        {"'abc' < 'abd'", "True"},
        {"'B' < 'a'", "True"},
        {"'' < 'a'", "True"},
        {"[1, 2] < [1, 3]", "True"},
        {"[1, 2] < [1, 2, 0]", "True"},
        {"[1, 2] == [1.0, 2]", "True"},
        {"[1, 'a'] != [1, 'b']", "True"},
    });
}

TEST(FormulaOperators, AndOrReturnAnOperand) {
    expectAll({
        {"[] or 5", "5"},
        {"0 or ''", "''"},
        {"3 and 4", "4"},
        {"0 and 4", "0"},
        {"'' or 'x'", "'x'"},
        {"None or 0.0", "0.0"},
        {"1 and 2 and 3", "3"},
        {"0 or 0 or 7", "7"},
        {"1 or undefined_setting", "1"},   // short-circuit: never looked up
        {"0 and undefined_setting", "0"},  // same for `and`
        {"True and not False", "True"},
        {"1 or 0 and 0", "1"},  // `and` binds tighter than `or`
        {"([] or 5) == 5", "True"},
    });
}

TEST(FormulaOperators, ConditionalExpression) {
    expectAll({
        {"1 if True else 2", "1"},
        {"1 if 0 else 2", "2"},
        {"'a' if [] else 'b' if 0 else 'c'", "'c'"},
        {"1 if 1 else undefined_setting", "1"},
        {"(1 if False else 2) * 3", "6"},
        {"1 + 2 if False else 3 + 4", "7"},
    });
}

TEST(FormulaOperators, Membership) {
    expectAll({
        {"'a' in 'abc'", "True"},
        {"'ac' in 'abc'", "False"},
        {"'' in 'abc'", "True"},
        {"'b' not in 'abc'", "False"},
        {"2 in [1, 2, 3]", "True"},
        {"2.0 in [1, 2, 3]", "True"},
        {"4 not in [1, 2, 3]", "True"},
        {"'x' in ('x', 'y')", "True"},
        {"'grid' not in ['cubicsubdiv', 'cross']", "True"},
        {"[1] in [[1], 2]", "True"},
        {"not 'a' in 'abc'", "False"},
    });
}

TEST(FormulaOperators, Subscripts) {
    expectAll({
        {"[10, 20, 30][0]", "10"},
        {"[10, 20, 30][-1]", "30"},
        {"[10, 20, 30][-3]", "10"},
        {"'abc'[1]", "'b'"},
        {"'abc'[-1]", "'c'"},
        {"[10, 20][True]", "20"},
        {"[[1, 2], [3, 4]][1][0]", "3"},
        {"(5, 6)[1]", "6"},
    });
}

TEST(FormulaOperators, SettingsComeFromTheEnvironment) {
    MapEnvironment env;
    env.settings["layer_height"] = 0.2;
    env.settings["wall_line_count"] = 3;
    env.settings["support_enable"] = false;
    env.settings["infill_pattern"] = "grid";
    EXPECT_EQ(eval("layer_height * wall_line_count", env), Value(0.6000000000000001));
    EXPECT_EQ(eval("wall_line_count // 2", env), Value(1));
    EXPECT_EQ(eval("'on' if support_enable else infill_pattern", env), Value("grid"));
    EXPECT_EQ(eval("infill_pattern in ['grid', 'lines']", env), Value(true));
}

}  // namespace
}  // namespace mixengine::formula::test
