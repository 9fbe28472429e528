#pragma once
// Helpers for the formula tests: an Environment backed by maps, and one-call parse + evaluate.
#include <gtest/gtest.h>

#include <functional>
#include <initializer_list>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "settings/formula/Formula.h"

namespace mixengine::formula::test {

class MapEnvironment : public Environment {
  public:
    using Function = std::function<Value(const std::vector<Value>&)>;

    std::map<std::string, Value, std::less<>> settings;
    std::map<std::string, Function, std::less<>> functions;

    std::optional<Value> lookup(std::string_view name) const override {
        const auto it = settings.find(name);
        if (it == settings.end())
            return std::nullopt;
        return it->second;
    }

    std::optional<Value> callFunction(std::string_view name, const std::vector<Value>& args) const override {
        const auto it = functions.find(name);
        if (it == functions.end())
            return std::nullopt;
        return it->second(args);
    }
};

inline Value eval(std::string_view source, const Environment& env) {
    return evaluate(parse(source), env);
}

inline Value eval(std::string_view source) {
    return eval(source, MapEnvironment{});
}

/// The Python repr() of the formula's result: compact to compare, and checks the type too
/// ("3" is an int, "3.0" a float, "True" a bool, "'3'" a str).
inline std::string repr(std::string_view source) {
    return toPythonRepr(eval(source));
}

/// A formula and the Python repr() of its result (checked against CPython 3).
struct Case {
    const char* formula;
    const char* repr;
};

/// Expects every case's repr; a FormulaError is reported as a failure of that case.
inline void expectAll(std::initializer_list<Case> cases) {
    for (const Case& c : cases) {
        try {
            EXPECT_EQ(repr(c.formula), c.repr) << "formula: " << c.formula;
        } catch (const FormulaError& e) {
            ADD_FAILURE() << "formula: " << c.formula << " threw " << e.what();
        }
    }
}

}  // namespace mixengine::formula::test
