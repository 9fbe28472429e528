// Tokenizer and parser: literals, line breaks, name resolution, referencedNames(), toPythonStr().
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "unit/formula/FormulaTestSupport.h"

namespace mixengine::formula::test {
namespace {

TEST(FormulaSyntax, StringLiteralsWithBothQuotesAndEscapes) {
    EXPECT_EQ(eval(R"('it\'s')"), Value("it's"));
    EXPECT_EQ(eval(R"("say \"hi\"")"), Value("say \"hi\""));
    EXPECT_EQ(eval(R"("it's")"), Value("it's"));
    EXPECT_EQ(eval(R"('a"b')"), Value("a\"b"));
    EXPECT_EQ(eval(R"('\n\t\\')"), Value("\n\t\\"));
    EXPECT_EQ(eval(R"('\x41\101\u00e9')"), Value("AA\xC3\xA9"));
    EXPECT_EQ(eval(R"('\d')"), Value("\\d"));  // unknown escapes stay as written
    EXPECT_EQ(eval(R"(r'\n')"), Value("\\n"));
    EXPECT_EQ(eval(R"(u'x')"), Value("x"));
    EXPECT_EQ(eval(R"('''a'b''')"), Value("a'b"));
    EXPECT_EQ(eval("\"\"\"x\ny\"\"\""), Value("x\ny"));
    EXPECT_EQ(eval(R"('a' "b" 'c')"), Value("abc"));
    EXPECT_EQ(eval(R"('')"), Value(""));
    EXPECT_EQ(eval(R"("G28 ;Home\nG1 Z15.0 F6000")"), Value("G28 ;Home\nG1 Z15.0 F6000"));
}

TEST(FormulaSyntax, NumberLiterals) {
    EXPECT_EQ(eval("1e-3"), Value(0.001));
    EXPECT_EQ(eval("1E3"), Value(1000.0));
    EXPECT_EQ(eval(".5"), Value(0.5));
    EXPECT_EQ(eval("0."), Value(0.0));
    EXPECT_EQ(eval("1.e2"), Value(100.0));
    EXPECT_EQ(eval("1_0.5"), Value(10.5));
    EXPECT_EQ(eval("0"), Value(0));
    EXPECT_EQ(eval("00"), Value(0));
    EXPECT_EQ(eval("0x1F"), Value(31));
    EXPECT_EQ(eval("0o17"), Value(15));
    EXPECT_EQ(eval("0b101"), Value(5));
    EXPECT_EQ(eval("9223372036854775807"), Value(std::int64_t{9223372036854775807}));
    EXPECT_EQ(eval("True"), Value(true));
    EXPECT_EQ(eval("None"), Value());
}

TEST(FormulaSyntax, LineBreaksInsideBracketsCommentsAndContinuations) {
    EXPECT_EQ(eval("(1 +\n 2)"), Value(3));
    EXPECT_EQ(eval("max(1,\n    2,\n)"), Value(2));
    EXPECT_EQ(eval("[1,\r\n 2]"), Value(List{1, 2}));
    EXPECT_EQ(eval("1 + \\\n 2"), Value(3));
    EXPECT_EQ(eval("1 # a comment"), Value(1));
    EXPECT_EQ(eval("(1 + # comment\n 2)"), Value(3));
    EXPECT_EQ(eval("  1 + 1\n\n"), Value(2));
    EXPECT_THROW(eval("1\n+ 2"), FormulaError);
}

TEST(FormulaSyntax, TuplesAndListsAreLists) {
    EXPECT_EQ(eval("(1, 2)"), Value(List{1, 2}));
    EXPECT_EQ(eval("(1,)"), Value(List{1}));
    EXPECT_EQ(eval("()"), Value(List{}));
    EXPECT_EQ(eval("[]"), Value(List{}));
    EXPECT_EQ(eval("[1, [2, 'a'],]"), Value(List{1, List{2, "a"}}));
    EXPECT_EQ(eval("1, 2"), Value(List{1, 2}));
    EXPECT_EQ(eval("(1)"), Value(1));
}

TEST(FormulaSyntax, BuiltinsAsValues) {
    EXPECT_EQ(eval("abs"), Value(FunctionRef{Builtin::Abs}));
    EXPECT_EQ(eval("math.sqrt"), Value(FunctionRef{Builtin::MathSqrt}));
    EXPECT_EQ(toPythonStr(eval("abs")), "<built-in function abs>");
    EXPECT_EQ(toPythonStr(eval("math.sqrt")), "<built-in function sqrt>");
    EXPECT_EQ(eval("(max)(1, 2)"), Value(2));
    EXPECT_EQ(eval("[f(-1) for f in [abs, float]]"), Value(List{1, -1.0}));
}

TEST(FormulaSyntax, EnvironmentFunctionsGetEvaluatedArguments) {
    MapEnvironment env;
    env.settings["support_extruder_nr"] = 1;
    std::vector<Value> seen;
    env.functions["extruderValue"] = [&](const std::vector<Value>& args) {
        seen = args;
        return Value(0.4);
    };
    env.functions["extruderValues"] = [](const std::vector<Value>&) { return Value(List{1.0, 3.0}); };
    EXPECT_EQ(eval("extruderValue(support_extruder_nr, 'line_width') * 2", env), Value(0.8));
    EXPECT_EQ(seen, (std::vector<Value>{1, "line_width"}));
    EXPECT_EQ(eval("max(extruderValues('x'))", env), Value(3.0));
    EXPECT_EQ(eval("sum(extruderValues('x')) / len(extruderValues('x'))", env), Value(2.0));
}

TEST(FormulaSyntax, ParseOnceEvaluateMany) {
    const Expression e = parse("layer_height * 2 if adaptive else 0");
    EXPECT_EQ(e.source(), "layer_height * 2 if adaptive else 0");
    MapEnvironment a;
    a.settings = {{"layer_height", 0.1}, {"adaptive", true}};
    MapEnvironment b;
    b.settings = {{"layer_height", 0.1}, {"adaptive", false}};
    EXPECT_EQ(evaluate(e, a), Value(0.2));
    EXPECT_EQ(evaluate(e, b), Value(0));
    EXPECT_EQ(evaluate(e, a), Value(0.2));
}

TEST(FormulaSyntax, ReferencedNames) {
    using Names = std::vector<std::string>;
    EXPECT_EQ(referencedNames(parse("resolveOrValue('layer_height') * 2 + wall_count if a else "
                                    "extruderValue(support_extruder_nr, 'speed')")),
              (Names{"a", "layer_height", "speed", "support_extruder_nr", "wall_count"}));
    EXPECT_EQ(
        referencedNames(parse("all(p != 'surface' for p in extruderValues('magic_mesh_surface_mode'))")),
        (Names{"magic_mesh_surface_mode"}));
    EXPECT_EQ(referencedNames(parse("max(math.pi, round(x, 2), x)")), (Names{"x"}));
    EXPECT_EQ(referencedNames(parse("'abc' + str(1)")), Names{});
    EXPECT_EQ(referencedNames(parse("int(defaultExtruderPosition())")), Names{});
}

TEST(FormulaSyntax, ToPythonStrAndRepr) {
    EXPECT_EQ(toPythonStr(Value(List{1, "a", 2.5, true, Value()})), "[1, 'a', 2.5, True, None]");
    EXPECT_EQ(toPythonStr(Value(List{List{1}, List{}})), "[[1], []]");
    EXPECT_EQ(toPythonStr(Value(List{"it's"})), "[\"it's\"]");
    EXPECT_EQ(toPythonStr(Value(List{"a\nb\\"})), "['a\\nb\\\\']");
    EXPECT_EQ(toPythonStr(Value(List{"both ' and \""})), "['both \\' and \"']");
    EXPECT_EQ(toPythonStr(Value("x")), "x");
    EXPECT_EQ(toPythonRepr(Value("x")), "'x'");
    EXPECT_EQ(toPythonStr(Value(false)), "False");
    EXPECT_EQ(toPythonStr(Value()), "None");
    EXPECT_EQ(toPythonStr(Value(-12)), "-12");
    EXPECT_EQ(floatRepr(1e22), "1e+22");
    EXPECT_EQ(floatRepr(0.0), "0.0");
    EXPECT_EQ(floatRepr(1234567890123456.0), "1234567890123456.0");
    EXPECT_EQ(floatRepr(12345678901234567.0), "1.2345678901234568e+16");
    EXPECT_EQ(floatRepr(0.001), "0.001");
    EXPECT_EQ(floatRepr(std::numeric_limits<double>::quiet_NaN()), "nan");
    EXPECT_EQ(floatRepr(-std::numeric_limits<double>::infinity()), "-inf");
}

TEST(FormulaSyntax, ValueEqualityAndTypes) {
    EXPECT_NE(Value(1), Value(1.0));
    EXPECT_NE(Value(true), Value(1));
    EXPECT_TRUE(pythonEquals(Value(1), Value(1.0)));
    EXPECT_TRUE(pythonEquals(Value(true), Value(1)));
    EXPECT_TRUE(pythonEquals(Value(List{1, 2.0}), Value(List{1.0, 2})));
    EXPECT_FALSE(pythonEquals(Value("1"), Value(1)));
    EXPECT_EQ(typeName(Value()), "NoneType");
    EXPECT_EQ(typeName(Value(2)), "int");
    EXPECT_EQ(typeName(Value(2.0)), "float");
    EXPECT_EQ(typeName(Value(List{})), "list");
    EXPECT_FALSE(truthy(Value(0.0)));
    EXPECT_TRUE(truthy(Value(std::nan(""))));
}

}  // namespace
}  // namespace mixengine::formula::test
