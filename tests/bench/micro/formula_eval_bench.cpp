// Formula evaluation speed: every value/resolve/enabled/... formula of Cura's fdmprinter and
// fdmextruder, parsed once, then evaluated against the definitions' defaults. Prints wall and CPU
// time; no threshold. That they parse and evaluate is tested in tests/unit/formula/FormulaCorpus_test.cpp.
#include <cstdio>

#include "bench/micro/Stopwatch.h"
#include "common/Error.h"
#include "unit/formula/FormulaCorpus.h"

int main() {
    using namespace mixengine::formula;
    if (!std::filesystem::exists(test::kCuraResources / "definitions" / "fdmprinter.def.json")) {
        std::printf("bench formula_eval: skipped (Cura definitions not installed in %s)\n",
                    test::kCuraResources.c_str());
        return 0;
    }
    std::vector<test::FormulaSource> formulas;
    std::map<std::string, Value, std::less<>> defaults;
    test::loadBaseDefinitions(formulas, defaults);
    const test::DefaultsEnvironment env(defaults);
    std::vector<Expression> parsed;
    for (const test::FormulaSource& f : formulas)
        parsed.push_back(parse(f.text));
    std::size_t evaluated = 0;
    const mixengine::bench::Timing t = mixengine::bench::timed([&] {
        for (const Expression& e : parsed) {
            try {
                evaluate(e, env);
                ++evaluated;
            } catch (const mixengine::InputError&) {
            }
        }
    });
    const std::string what = std::to_string(evaluated) + " of " + std::to_string(parsed.size()) +
                             " parsed fdmprinter/fdmextruder formulas evaluated";
    mixengine::bench::printTiming("formula_eval", t, what.c_str());
    return 0;
}
