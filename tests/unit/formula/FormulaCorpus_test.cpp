// Every formula in Cura's definitions must parse; those of fdmprinter/fdmextruder must evaluate
// against the definitions' own default values. How fast they evaluate is measured, not asserted:
// tests/bench/micro/formula_eval_bench.cpp (tests/bench/micro.sh).
#include <gtest/gtest.h>

#include <iostream>

#include "unit/formula/FormulaCorpus.h"

namespace mixengine::formula::test {
namespace {

struct Tally {
    std::size_t ok = 0;
    std::size_t total = 0;
    std::vector<std::string> failures;

    double fraction() const {
        return total == 0 ? 1.0 : static_cast<double>(ok) / static_cast<double>(total);
    }

    void report(const std::string& title) const {
        std::cout << "[ corpus   ] " << title << ": " << ok << "/" << total << " evaluated OK\n";
        for (const std::string& f : failures)
            std::cout << "[ failure  ]   " << f << "\n";
    }
};

bool isValueOrResolve(const FormulaSource& f) {
    return f.property == "value" || f.property == "resolve";
}

Tally evaluateAll(const std::vector<FormulaSource>& formulas, const Environment& env, bool valueOrResolve) {
    Tally tally;
    for (const FormulaSource& f : formulas) {
        if (isValueOrResolve(f) != valueOrResolve)
            continue;
        ++tally.total;
        try {
            evaluate(parse(f.text), env);
            ++tally.ok;
        } catch (const InputError& e) {
            tally.failures.push_back(f.file + " " + f.key + "." + f.property + ": " + e.what());
        }
    }
    return tally;
}

class FormulaCorpus : public ::testing::Test {
  protected:
    void SetUp() override {
        if (!std::filesystem::exists(kCuraResources / "definitions" / "fdmprinter.def.json")) {
            GTEST_SKIP() << "Cura definitions not installed in " << kCuraResources;
        }
        loadBaseDefinitions(base_, defaults_);
        overrides_ = loadOverrideFormulas();
    }

    std::vector<FormulaSource> base_;
    std::vector<FormulaSource> overrides_;
    std::map<std::string, Value, std::less<>> defaults_;
};

TEST_F(FormulaCorpus, EveryDefinitionFormulaParses) {
    std::size_t parsed = 0;
    std::vector<FormulaSource> all = base_;
    all.insert(all.end(), overrides_.begin(), overrides_.end());
    for (const FormulaSource& f : all) {
        try {
            parse(f.text);
            ++parsed;
        } catch (const FormulaError& e) {
            ADD_FAILURE() << f.file << " " << f.key << "." << f.property << ": " << e.what();
        }
    }
    std::cout << "[ corpus   ] parsed " << parsed << "/" << all.size() << " formulas (" << base_.size()
              << " in fdmprinter+fdmextruder, " << overrides_.size() << " in machine/extruder overrides)\n";
    EXPECT_EQ(parsed, all.size());
    EXPECT_GT(all.size(), 4000u);
}

TEST_F(FormulaCorpus, BaseValueAndResolveFormulasEvaluate) {
    const DefaultsEnvironment env(defaults_);
    const Tally tally = evaluateAll(base_, env, true);
    tally.report("fdmprinter+fdmextruder value/resolve");
    EXPECT_GE(tally.fraction(), 0.99);
    EXPECT_GT(tally.total, 250u);
}

TEST_F(FormulaCorpus, BaseConditionAndLimitFormulasEvaluate) {
    const DefaultsEnvironment env(defaults_);
    const Tally tally = evaluateAll(base_, env, false);
    tally.report("fdmprinter+fdmextruder enabled/minimum/maximum/warnings");
    EXPECT_GE(tally.fraction(), 0.99);
}

TEST_F(FormulaCorpus, MachineOverrideFormulasEvaluate) {
    const DefaultsEnvironment env(defaults_);
    const Tally values = evaluateAll(overrides_, env, true);
    values.report("machine/extruder overrides value/resolve");
    const Tally others = evaluateAll(overrides_, env, false);
    others.report("machine/extruder overrides enabled/minimum/maximum/warnings");
    EXPECT_GE(values.fraction(), 0.99);
    EXPECT_GE(others.fraction(), 0.99);
}

}  // namespace
}  // namespace mixengine::formula::test
