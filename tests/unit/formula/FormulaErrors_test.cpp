// Invalid formulas throw FormulaError (an InputError) naming the formula and the problem; nothing
// crashes, whatever the input.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "unit/formula/FormulaTestSupport.h"

namespace mixengine::formula::test {
namespace {

// The FormulaError of evaluating `formula` (parse or runtime); fails the test if there is none.
FormulaError errorOf(const std::string& formula, const Environment& env = MapEnvironment{}) {
    try {
        evaluate(parse(formula), env);
    } catch (const FormulaError& e) {
        return e;
    }
    ADD_FAILURE() << "no FormulaError for: " << formula;
    return FormulaError(formula, "(none)");
}

void expectError(const std::string& formula, const std::string& problemPart) {
    const FormulaError e = errorOf(formula);
    EXPECT_EQ(e.formula(), formula);
    EXPECT_NE(e.problem().find(problemPart), std::string::npos) << formula << " -> " << e.what();
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "one line: " << e.what();
}

TEST(FormulaErrors, MessageNamesTheFormulaAndTheProblem) {
    const FormulaError e = errorOf("1 / 0");
    EXPECT_STREQ(e.what(), "formula '1 / 0': division by zero");
    const InputError& asInput = e;
    EXPECT_STREQ(asInput.what(), "formula '1 / 0': division by zero");
    const FormulaError unknown = errorOf("no_such_setting + 1");
    EXPECT_STREQ(unknown.what(), "formula 'no_such_setting + 1': unknown name 'no_such_setting'");
    const FormulaError multiLine = errorOf("(1 +\n 'a')");
    EXPECT_STREQ(multiLine.what(),
                 "formula '(1 +\\n 'a')': unsupported operand type(s) for +: 'int' and 'str'");
}

TEST(FormulaErrors, SyntaxErrors) {
    expectError("1 +", "unexpected end of formula");
    expectError("(1", "unexpected end");
    expectError("[1, 2", "unexpected end");
    expectError("1 2", "unexpected '2'");
    expectError("1 +* 2", "unexpected '*'");
    expectError("foo(", "unexpected end");
    expectError("'abc", "unterminated string");
    expectError("'a\nb'", "unterminated string");
    expectError("a if b", "unexpected end");
    expectError(")", "unexpected ')'");
    expectError("", "unexpected end");
    expectError("   ", "unexpected end");
    expectError("1\n+ 2", "line 2 column 1: unexpected '+'");
    expectError("01", "leading zeros");
    expectError("1j", "imaginary");
    expectError("b'x'", "bytes");
    expectError("$", "unexpected character '$'");
    expectError("1 \\ 2", "line continuation");
    expectError("0x", "invalid integer literal");
    expectError("99999999999999999999", "does not fit in 64 bits");
    expectError("'\\xZZ'", "truncated");
}

TEST(FormulaErrors, UnsupportedSyntax) {
    expectError("lambda x: x", "lambda");
    expectError("{1: 2}", "dict and set");
    expectError("[1, 2][0:1]", "slices");
    expectError("a.b", "attribute access");
    expectError("'a'.upper()", "attribute access");
    expectError("math", "math.<member>");
    expectError("math.nope(1)", "unknown function or constant 'math.nope'");
    expectError("round(x=1)", "keyword arguments");
    expectError("max(*[1])", "unpacking");
    expectError("x is None", "'is'");
    expectError("~1", "bitwise");
    expectError("1 & 2", "unexpected '&'");
    expectError("max(x for x in [1], 2)", "unexpected ','");
    expectError("[x for x, y in []]", "tuple targets");
    expectError("1 if True else", "unexpected end");
}

TEST(FormulaErrors, UnknownNamesAndFunctions) {
    expectError("no_such_setting * 2", "unknown name 'no_such_setting'");
    expectError("frobnicate(1)", "unknown function 'frobnicate'");
    expectError("[x for x in [1]] + [x]", "unknown name 'x'");  // comprehension variables do not leak
}

TEST(FormulaErrors, DivisionByZero) {
    expectError("1 / 0", "division by zero");
    expectError("1 // 0", "division or modulo by zero");
    expectError("1 % 0", "division or modulo by zero");
    expectError("1.0 / 0.0", "division by zero");
    expectError("1.5 // 0", "division by zero");
    expectError("5 % 0.0", "modulo by zero");
    expectError("0 ** -1", "0.0 cannot be raised to a negative power");
    expectError("math.log(2, 1)", "division by zero");
}

TEST(FormulaErrors, TypeErrors) {
    expectError("'a' + 1", "unsupported operand type(s) for +: 'str' and 'int'");
    expectError("[1] * 1.5", "unsupported operand type(s) for *");
    expectError("None + 1", "'NoneType' and 'int'");
    expectError("1 < 'a'", "'<' not supported between instances of 'int' and 'str'");
    expectError("None < 1", "'<' not supported");
    expectError("-'a'", "bad operand type for unary -");
    expectError("'%d' % 3", "string formatting");
    expectError("1 in 5", "not iterable");
    expectError("1 in 'abc'", "requires string as left operand");
    expectError("len(5)", "has no len()");
    expectError("abs('a')", "bad operand type for abs()");
    expectError("(1)(2)", "'int' object is not callable");
    expectError("map(1, [1])", "not callable");
    expectError("sum(['a'])", "unsupported operand type(s) for +");
    expectError("sum([1], 'a')", "can't sum strings");
    expectError("round('a')", "__round__");
    expectError("round(1.5, 1.0)", "cannot be interpreted as an integer");
    expectError("sorted([1, 'a'])", "not supported between");
    expectError("math.sqrt('a')", "must be real number");
    expectError("int([])", "int() argument");
    expectError("float(None)", "float() argument");
    expectError("[1][0.0]", "list indices must be integers");
    expectError("1[0]", "not subscriptable");
    expectError("[1][5]", "list index out of range");
    expectError("''[0]", "string index out of range");
    expectError("any(5)", "not iterable");
}

TEST(FormulaErrors, ArgumentCounts) {
    expectError("abs(1, 2)", "abs() takes exactly 1 argument(s) (2 given)");
    expectError("len()", "len() takes exactly 1");
    expectError("round(1, 2, 3)", "round() takes from 1 to 2 argument(s) (3 given)");
    expectError("max()", "max() takes at least 1 argument(s) (0 given)");
    expectError("math.atan2(1)", "math.atan2() takes exactly 2");
}

TEST(FormulaErrors, ValueErrors) {
    expectError("int('x')", "invalid literal for int() with base 10: 'x'");
    expectError("int('12.5')", "invalid literal for int()");
    expectError("int('1__0')", "invalid literal for int()");
    expectError("float('abc')", "could not convert string to float: 'abc'");
    expectError("float('1e')", "could not convert string to float");
    expectError("max([])", "max() arg is an empty sequence");
    expectError("min('')", "min() arg is an empty sequence");
    expectError("math.sqrt(-1)", "math domain error");
    expectError("math.log(0)", "math domain error");
    expectError("math.log10(-1)", "math domain error");
    expectError("math.asin(2)", "math domain error");
    expectError("math.sin(math.inf)", "math domain error");
    expectError("math.pow(-8, 1 / 3)", "math domain error");
    expectError("(-8) ** (1 / 3)", "fractional power");
    expectError("math.exp(1000)", "math range error");
    expectError("10.0 ** 400", "out of range");
    expectError("int(float('inf'))", "cannot convert float infinity to integer");
    expectError("round(float('nan'))", "cannot convert float NaN to integer");
    expectError("math.ceil(1e300)", "does not fit in 64 bits");
    expectError("int('99999999999999999999')", "does not fit in 64 bits");
    expectError("round(1.7976931348623157e308, -308)", "too large");
}

TEST(FormulaErrors, HostileInputIsRefusedNotCrashed) {
    expectError(std::string(1000, '(') + "1" + std::string(1000, ')'), "nested too deeply");
    expectError(std::string(1000, '-') + "1", "nested too deeply");
    expectError(std::string(1000, '[') + std::string(1000, ']'), "nested too deeply");
    std::string longSum = "1";
    for (int i = 0; i < 5000; ++i)
        longSum += "+1";
    expectError(longSum, "nested too deeply");
    expectError("'ab' * 10 ** 9", "too large");
    expectError("[0] * 10 ** 9", "too large");
    std::string shortSum = "1";
    for (int i = 0; i < 500; ++i)
        shortSum += "+1";
    EXPECT_EQ(eval(shortSum), Value(501));
}

// Random sequences of formula fragments either evaluate or throw FormulaError; nothing else.
TEST(FormulaErrors, RandomInputOnlyEverThrowsFormulaError) {
    const std::vector<std::string> fragments = {
        "(",    ")",      "[",    "]",     ",",  "1",   "0",   "-2.5",  "1e308", "'a'",  "\"b\"", "'",
        "+",    "-",      "*",    "/",     "//", "%",   "**",  "<",     "==",    "not ", " and ", " or ",
        " if ", " else ", " in ", " for ", "x",  "abs", "max", "round", "math.", "sqrt", "pi",    "str",
        "int",  "len",    "sum",  "map",   "\n", "\\",  ".",   "True",  "None",  "#",    "é"};
    MapEnvironment env;
    env.settings["x"] = List{1, 2.5, "s"};
    std::mt19937 rng(12345);
    std::size_t evaluated = 0;
    for (int i = 0; i < 20000; ++i) {
        std::string formula;
        const int length = 1 + static_cast<int>(rng() % 12);
        for (int k = 0; k < length; ++k)
            formula += fragments[rng() % fragments.size()];
        try {
            evaluate(parse(formula), env);
            ++evaluated;
        } catch (const FormulaError&) {
        } catch (const std::exception& e) {
            ADD_FAILURE() << "formula " << formula << " threw a non-FormulaError: " << e.what();
        }
    }
    EXPECT_GT(evaluated, 100u);
}

TEST(FormulaErrors, LongFormulasAreShortenedInTheMessage) {
    const std::string formula = "'" + std::string(300, 'x') + "' + 1";
    const FormulaError e = errorOf(formula);
    EXPECT_EQ(e.formula(), formula);
    EXPECT_LT(std::string(e.what()).size(), 250u);
    EXPECT_NE(std::string(e.what()).find("...': unsupported operand"), std::string::npos) << e.what();
}

TEST(FormulaErrors, EnvironmentErrorsPassThrough) {
    MapEnvironment env;
    env.functions["resolveOrValue"] = [](const std::vector<Value>&) -> Value {
        throw FormulaError("layer_height * 2", "unknown name 'layer_height'");
    };
    try {
        eval("resolveOrValue('x') + 1", env);
        ADD_FAILURE() << "no exception";
    } catch (const FormulaError& e) {
        EXPECT_EQ(e.formula(), "layer_height * 2");
    }
}

}  // namespace
}  // namespace mixengine::formula::test
