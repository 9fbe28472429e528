// Python semantics of the built-in functions and the math module. Each case is a formula and the
// Python repr() of its result (checked against CPython 3).
#include <gtest/gtest.h>

#include "unit/formula/FormulaTestSupport.h"

namespace mixengine::formula::test {
namespace {

TEST(FormulaBuiltins, RoundIsBankersAndCorrectlyRounded) {
    expectAll({
        {"round(2.5)", "2"},
        {"round(3.5)", "4"},
        {"round(-2.5)", "-2"},
        {"round(0.5)", "0"},
        {"round(2.6)", "3"},
        {"round(True)", "1"},
        {"round(7)", "7"},
        {"round(0.125, 2)", "0.12"},
        {"round(0.375, 2)", "0.38"},
        {"round(2.675, 2)", "2.67"},
        {"round(1.23456789, 4)", "1.2346"},
        {"round(2.5, 0)", "2.0"},
        {"round(3.5, 0)", "4.0"},
        {"round(-0.001, 2)", "-0.0"},
        {"round(1234.5678, -2)", "1200.0"},
        {"round(1250.0, -2)", "1200.0"},
        {"round(1e20, 2)", "1e+20"},
        {"round(5e-324, 400)", "5e-324"},
        {"round(0.1 + 0.2, 3)", "0.3"},
        {"round(7, 2)", "7"},
        {"round(1250, -2)", "1200"},
        {"round(1350, -2)", "1400"},
        {"round(-1250, -2)", "-1200"},
        {"round(-1251, -2)", "-1300"},
        {"round(2.5, None)", "2"},
    });
}

TEST(FormulaBuiltins, IntFloatStrBool) {
    expectAll({
        {"int(-2.7)", "-2"},
        {"int(2.7)", "2"},
        {"int('12')", "12"},
        {"int(' -12 ')", "-12"},
        {"int('+7')", "7"},
        {"int('1_000')", "1000"},
        {"int('007')", "7"},
        {"int(True)", "1"},
        {"int()", "0"},
        {"int(1e15)", "1000000000000000"},
        {"float('1.5')", "1.5"},
        {"float(' -1e3 ')", "-1000.0"},
        {"float('.5')", "0.5"},
        {"float('inf')", "inf"},
        {"float('-Infinity')", "-inf"},
        {"float(3)", "3.0"},
        {"float(False)", "0.0"},
        {"float()", "0.0"},
        {"float('1e400')", "inf"},
        {"bool(0)", "False"},
        {"bool(0.0)", "False"},
        {"bool('a')", "True"},
        {"bool([])", "False"},
        {"bool([0])", "True"},
        {"bool(None)", "False"},
        {"bool()", "False"},
    });
}

TEST(FormulaBuiltins, StrUsesPythonsShortestFloatRepr) {
    expectAll({
        {"str(0.1)", "'0.1'"},
        {"str(1.0)", "'1.0'"},
        {"str(0.1 + 0.2)", "'0.30000000000000004'"},
        {"str(1e16)", "'1e+16'"},
        {"str(1e15)", "'1000000000000000.0'"},
        {"str(123456789012345678.0)", "'1.2345678901234568e+17'"},
        {"str(0.0001)", "'0.0001'"},
        {"str(0.00001)", "'1e-05'"},
        {"str(-0.0)", "'-0.0'"},
        {"str(1.5e-7)", "'1.5e-07'"},
        {"str(123456789.123)", "'123456789.123'"},
        {"str(2 ** 0.5)", "'1.4142135623730951'"},
        {"str(1 / 3)", "'0.3333333333333333'"},
        {"str(100.0)", "'100.0'"},
        {"str(5e-324)", "'5e-324'"},
        {"str(1.7976931348623157e308)", "'1.7976931348623157e+308'"},
        {"str(7)", "'7'"},
        {"str(-7)", "'-7'"},
        {"str(True)", "'True'"},
        {"str(None)", "'None'"},
        {"str('x')", "'x'"},
        {"str([1, 'a', 2.0, True, None])", "\"[1, 'a', 2.0, True, None]\""},
        {"str([[1, 2], []])", "'[[1, 2], []]'"},
        {"str()", "''"},
    });
}

TEST(FormulaBuiltins, MinMaxSumLenAbs) {
    expectAll({
        {"min(3, 1, 2)", "1"},
        {"max([1, 5, 3])", "5"},
        {"max(1, 2.5)", "2.5"},
        {"max(2, 2.0)", "2"},
        {"max(2.0, 2)", "2.0"},
        {"min([4])", "4"},
        {"min(0.3, 0.1 + 0.2)", "0.3"},
        {"max('abc')", "'c'"},
        {"max([1, 2], [1, 3])", "[1, 3]"},
        {"max(True, 0)", "True"},
        {"sum([1, 2, 3])", "6"},
        {"sum([1, 2.5])", "3.5"},
        {"sum([])", "0"},
        {"sum([True, True])", "2"},
        {"sum([1, 2], 10)", "13"},
        {"sum([[1], [2]], [])", "[1, 2]"},
        {"sum([0.1] * 10)", "0.9999999999999999"},
        {"len([1, 2, 3])", "3"},
        {"len('abcd')", "4"},
        {"len([])", "0"},
        {"abs(-3)", "3"},
        {"abs(-2.5)", "2.5"},
        {"abs(True)", "1"},
        {"abs(-0.0)", "0.0"},
    });
}

TEST(FormulaBuiltins, AnyAllMapListSorted) {
    expectAll({
        {"any([0, '', 3])", "True"},
        {"any([])", "False"},
        {"any([0, None])", "False"},
        {"all([1, 'a'])", "True"},
        {"all([])", "True"},
        {"all([1, 0])", "False"},
        {"list(map(abs, [-1, 2, -3]))", "[1, 2, 3]"},
        {"max(map(abs, [-1, 2, -3]))", "3"},
        {"list(map(max, [1, 5], [4, 2]))", "[4, 5]"},
        {"list(map(str, [1, 2.0]))", "['1', '2.0']"},
        {"list(map(math.sqrt, [4]))", "[2.0]"},
        {"list('ab')", "['a', 'b']"},
        {"list([1, 2])", "[1, 2]"},
        {"list()", "[]"},
        {"sorted([3, 1, 2])", "[1, 2, 3]"},
        {"sorted(['b', 'a', 'c'])", "['a', 'b', 'c']"},
        {"sorted([2, 1.5, True])", "[True, 1.5, 2]"},
        {"sorted([1, True, 1.0])", "[1, True, 1.0]"},
    });
}

TEST(FormulaBuiltins, Comprehensions) {
    expectAll({
        {"all(p != 'surface' for p in ['normal', 'both'])", "True"},
        {"all((p != 'surface' for p in ['normal', 'surface']))", "False"},
        {"any(x > 2 for x in [1, 2, 3])", "True"},
        {"sum(x * x for x in [1, 2, 3])", "14"},
        {"[x * 2 for x in [1, 2, 3] if x != 2]", "[2, 6]"},
        {"[x + y for x in [1, 2] for y in [10, 20]]", "[11, 21, 12, 22]"},
        {"[[y for y in [x, x]] for x in [1, 2]]", "[[1, 1], [2, 2]]"},
        {"[x for x in [1, 2, 3] if x > 1 if x < 3]", "[2]"},
        {"[c for c in 'ab']", "['a', 'b']"},
        {"[x for x in [[1, 2], [3]] for x in x]", "[1, 2, 3]"},
        {"[max for max in [1, 2]]", "[1, 2]"},
    });
}

TEST(FormulaBuiltins, MathModule) {
    expectAll({
        {"math.ceil(2.1)", "3"},
        {"math.ceil(-2.1)", "-2"},
        {"math.ceil(5)", "5"},
        {"math.ceil(2.0)", "2"},
        {"math.floor(2.9)", "2"},
        {"math.floor(-2.1)", "-3"},
        {"math.trunc(-2.7)", "-2"},
        {"math.sqrt(16)", "4.0"},
        {"math.sqrt(2)", "1.4142135623730951"},
        {"math.log(math.e)", "1.0"},
        {"math.log(8, 2)", "3.0"},
        {"math.log(100, 10)", "2.0"},
        {"math.log10(1000)", "3.0"},
        {"math.log2(8)", "3.0"},
        {"math.exp(0)", "1.0"},
        {"math.exp(1)", "2.718281828459045"},
        {"math.pi", "3.141592653589793"},
        {"math.e", "2.718281828459045"},
        {"math.tau", "6.283185307179586"},
        {"math.inf", "inf"},
        {"-math.inf", "-inf"},
        {"math.tan(0)", "0.0"},
        {"math.tan(math.radians(45))", "0.9999999999999999"},
        {"math.atan(1) * 4", "3.141592653589793"},
        {"math.sin(0)", "0.0"},
        {"math.cos(0)", "1.0"},
        {"math.asin(1)", "1.5707963267948966"},
        {"math.acos(1)", "0.0"},
        {"math.atan2(1, 1)", "0.7853981633974483"},
        {"math.radians(180)", "3.141592653589793"},
        {"math.degrees(math.pi)", "180.0"},
        {"math.degrees(math.atan(1))", "45.0"},
        {"math.fabs(-3)", "3.0"},
        {"math.pow(2, 3)", "8.0"},
        {"math.isclose(0.1 + 0.2, 0.3)", "True"},
        {"math.isclose(1, 1.1)", "False"},
        {"math.hypot(3, 4)", "5.0"},
    });
}

}  // namespace
}  // namespace mixengine::formula::test
