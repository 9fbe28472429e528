// Bounds on the work of parsing and evaluating a formula: whatever the formula, it ends quickly with a
// value or a FormulaError.
#include <gtest/gtest.h>

#include <string>

#include "unit/formula/FormulaTestSupport.h"

namespace mixengine::formula::test {
namespace {

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
