// The bounds of one formula evaluation (settings/formula/Budget.h): at most 1,000,000 elements (list
// items and string characters, copies included) and 1,000,000 steps; sizes are checked before the
// memory is allocated. Whatever the formula, it ends quickly with a value or a FormulaError.
#include <gtest/gtest.h>

#include <string>

#include "unit/formula/FormulaTestSupport.h"

namespace mixengine::formula::test {
namespace {

const std::string kTooLarge = "too large (more than 1000000 elements: list items and string characters)";
const std::string kTooMuchWork = "too much work (more than 1000000 evaluation steps)";

// The problem of the FormulaError that evaluating `formula` throws; fails the test on no error or on
// any other exception.
std::string problemOf(const std::string& formula, const Environment& env = MapEnvironment{}) {
    try {
        evaluate(parse(formula), env);
    } catch (const FormulaError& e) {
        EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
        return e.problem();
    } catch (...) {
        ADD_FAILURE() << "not a FormulaError for: " << formula;
        return "";
    }
    ADD_FAILURE() << "no FormulaError for: " << formula;
    return "";
}

TEST(FormulaBounds, RepetitionCountsNestedItemsBeforeAllocating) {
    // 1000 copies of a 500-item list and of the outer item: 501,000 elements, allowed.
    EXPECT_EQ(repr("len([[0] * 500] * 1000)"), "1000");
    EXPECT_EQ(repr("sum(map(len, [[0] * 250] * 1000))"), "250000");
    // 2000 copies: 1,002,000 elements (each copy of the inner list is a copy of its 500 items).
    EXPECT_EQ(problemOf("[[0] * 500] * 2000"), kTooLarge);
    EXPECT_EQ(problemOf("[0] * 1000001"), kTooLarge);
    EXPECT_EQ(problemOf("'ab' * 500001"), kTooLarge);
    EXPECT_EQ(problemOf("[0] * 10 ** 18"), kTooLarge);  // no overflow of size * count
    EXPECT_EQ(problemOf("[[0] * 10 ** 5] * 10 ** 18"), kTooLarge);
    EXPECT_EQ(repr("len('ab' * 250000)"), "500000");
    EXPECT_EQ(repr("[0] * -5"), "[]");
    EXPECT_EQ(repr("[] * 10 ** 18"), "[]");
}

TEST(FormulaBounds, ElementsAddUpOverTheWholeEvaluation) {
    // Each part is allowed alone; together they go over.
    EXPECT_EQ(repr("len([0] * 750000)"), "750000");
    EXPECT_EQ(problemOf("len([0] * 750000) + len([0] * 750000)"), kTooLarge);
    // Copies count: a variable holding 10,000 items, copied 300 times.
    EXPECT_EQ(problemOf("[xs for xs in [[0] * 10000] for i in 'x' * 300]"), kTooLarge);
    // Concatenation: sum() of lists copies the growing total each time (quadratic).
    EXPECT_EQ(problemOf("sum([[0] * 100] * 1000, [])"), kTooLarge);
    EXPECT_EQ(repr("len(sum([[0] * 10] * 100, []))"), "1000");
    EXPECT_EQ(problemOf("['x' * 100000 for c in 'abcdefghijklmnopqrstuvwxyz']"), kTooLarge);
}

TEST(FormulaBounds, StepsBoundNestedComprehensionsThatBuildNothing) {
    EXPECT_EQ(problemOf("[0 for a in [0] * 2000 for b in [0] * 2000 if a + b + a + b]"), kTooMuchWork);
    EXPECT_EQ(problemOf("any(1 for a in [0] * 100 for b in [0] * 100 for c in [0] * 100 if a + b + c)"),
              kTooMuchWork);
    EXPECT_EQ(problemOf("sorted([1] * 100000)"), kTooMuchWork);  // n log n comparisons
    EXPECT_EQ(repr("len([0 for a in 'x' * 300 for b in 'x' * 300 if 0])"), "0");
    EXPECT_EQ(repr("sorted([3, 1, 2] * 1000)[1500]"), "2");
}

TEST(FormulaBounds, EnvironmentValuesCountWhenCopied) {
    MapEnvironment env;
    env.settings["big"] = Value(List(50000, Value(std::int64_t{1})));
    EXPECT_EQ(toPythonRepr(eval("len([len(big) for i in 'x' * 10])", env)), "10");
    EXPECT_EQ(problemOf("[big for i in 'x' * 30]", env), kTooLarge);
}

TEST(FormulaBounds, StringSearchAndIndexingStayLinear) {
    // std::string::find would compare ~2 * 10^10 characters here; the search is linear.
    const std::string needle = "'a' * 150000 + 'b'";
    EXPECT_EQ(repr("(" + needle + ") in 'a' * 300000"), "False");
    EXPECT_EQ(repr("(" + needle + ") in 'a' * 300000 + 'b'"), "True");
    EXPECT_EQ(repr("'abcabcabd' + 'x' * 20 in 'abcabcabcabd' + 'x' * 20 + 'y'"), "True");
    EXPECT_EQ(repr("'abababababababababac' in 'ab' * 50 + 'ac'"), "True");
    EXPECT_EQ(repr("'abababababababababac' in 'ab' * 50 + 'ad'"), "False");
    EXPECT_EQ(repr("'' in 'abc'"), "True");
    EXPECT_EQ(repr("len('\xc3\xa9' * 400000)"), "400000");  // é, 2 bytes
    EXPECT_EQ(repr("('a\xc3\xa9' * 300000)[-1]"), "'\xc3\xa9'");
    EXPECT_EQ(repr("('a\xc3\xa9' * 300000)[599998]"), "'a'");
    EXPECT_EQ(repr("[c for c in 'a\xc3\xa9"
                   "b']"),
              "['a', '\xc3\xa9', 'b']");
}

TEST(FormulaBounds, AProblemQuotingAHugeValueIsShortened) {
    const std::string problem = problemOf("int('1' * 100000)");
    EXPECT_EQ(problem.size(), 300U);
    EXPECT_EQ(problem.rfind("integer overflow in int(): 111", 0), 0U) << problem;
    EXPECT_EQ(problem.substr(297), "...");
}

TEST(FormulaBounds, ParsingNestedComprehensionsIsLinear) {
    // Each level was parsed twice (once to find the element's end): 2^60 parses of the innermost.
    std::string formula = "0";
    for (int i = 0; i < 60; ++i)
        formula = "[" + formula + " for a" + std::to_string(i) + " in [1]]";
    std::string expected = "0";
    for (int i = 0; i < 60; ++i)
        expected = "[" + expected + "]";
    EXPECT_EQ(repr(formula), expected);
    EXPECT_EQ(repr("all(x > 0 for x in [y for y in [1, 2] if y])"), "True");
    EXPECT_EQ(repr("[[a * b for b in [1, 2]] for a in [3, 4]]"), "[[3, 6], [4, 8]]");
    EXPECT_EQ(repr("[(a, b) for a in [1] for b in [a + 1]]"), "[[1, 2]]");
}

}  // namespace
}  // namespace mixengine::formula::test
