#include "settings/formula/Builtins.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <string>

#include "settings/formula/FormulaError.h"
#include "settings/formula/Numeric.h"
#include "settings/formula/Operators.h"

namespace mixengine::formula {

namespace {

using detail::Budget;
using detail::EvalProblem;

constexpr int kVariadic = -1;

using Args = std::vector<Value>;

struct BuiltinInfo {
    Builtin id;
    std::string_view name;
    int minArgs;
    int maxArgs;
    Value (*call)(const Args& args, Budget& budget);  ///< nullptr for math.*: callMathBuiltin
};

void checkArgCount(const BuiltinInfo& b, std::size_t given) {
    const auto n = static_cast<int>(given);
    if (n >= b.minArgs && (b.maxArgs == kVariadic || n <= b.maxArgs))
        return;
    std::string expected;
    if (b.minArgs == b.maxArgs) {
        expected = "exactly " + std::to_string(b.minArgs);
    } else if (b.maxArgs == kVariadic) {
        expected = "at least " + std::to_string(b.minArgs);
    } else {
        expected = "from " + std::to_string(b.minArgs) + " to " + std::to_string(b.maxArgs);
    }
    throw EvalProblem(std::string(b.name) + "() takes " + expected + " argument(s) (" +
                      std::to_string(given) + " given)");
}

bool isIntLike(const Value& v) {
    return v.is<bool>() || v.is<std::int64_t>();
}

Value absValue(const Value& v) {
    if (v.is<double>())
        return std::fabs(v.as<double>());
    if (isIntLike(v))
        return asInt(v) < 0 ? negInt(asInt(v)) : asInt(v);
    throw EvalProblem("bad operand type for abs(): '" + std::string(typeName(v)) + "'");
}

Value toFloat(const Value& v) {
    if (v.isNumber())
        return asDouble(v);
    if (v.is<std::string>())
        return parseFloatString(v.as<std::string>());
    throw EvalProblem("float() argument must be a string or a real number, not '" + std::string(typeName(v)) +
                      "'");
}

Value toInt(const Value& v) {
    if (isIntLike(v))
        return asInt(v);
    if (v.is<double>())
        return truncToInt(v.as<double>());
    if (v.is<std::string>())
        return parseIntString(v.as<std::string>());
    throw EvalProblem("int() argument must be a string or a real number, not '" + std::string(typeName(v)) +
                      "'");
}

Value length(const Value& v) {
    if (v.is<std::string>())
        return characterCount(v.as<std::string>());
    if (v.is<List>())
        return v.as<List>().size();
    throw EvalProblem("object of type '" + std::string(typeName(v)) + "' has no len()");
}

Value mapValues(const std::vector<Value>& args, Budget& budget) {
    if (!args[0].is<FunctionRef>()) {
        throw EvalProblem("map(): '" + std::string(typeName(args[0])) + "' object is not callable");
    }
    std::vector<List> iterables;
    std::size_t shortest = SIZE_MAX;
    for (std::size_t i = 1; i < args.size(); ++i) {
        iterables.push_back(iterate(args[i], "map()", budget));
        shortest = std::min(shortest, iterables.back().size());
    }
    List out;
    for (std::size_t k = 0; k < shortest; ++k) {
        budget.step();
        std::vector<Value> callArgs;
        for (const List& it : iterables)
            callArgs.push_back(it[k]);
        out.push_back(callBuiltin(args[0].as<FunctionRef>().id, callArgs, budget));
        budget.take(1);
    }
    return out;
}

Value extreme(const std::vector<Value>& args, bool wantMax, Budget& budget) {
    const char* name = wantMax ? "max" : "min";
    const List iterated = args.size() == 1 ? iterate(args[0], std::string(name) + "()", budget) : List();
    const List& items = args.size() == 1 ? iterated : args;
    if (items.empty())
        throw EvalProblem(std::string(name) + "() arg is an empty sequence");
    budget.step(items.size());
    const Value* best = &items[0];
    for (std::size_t i = 1; i < items.size(); ++i) {
        const auto order = pythonOrder(items[i], *best, wantMax ? ">" : "<");
        if (wantMax ? order > 0 : order < 0)
            best = &items[i];
    }
    return *best;
}

Value roundValue(const std::vector<Value>& args) {
    const Value& x = args[0];
    if (!x.isNumber())
        throw EvalProblem("type " + std::string(typeName(x)) + " doesn't define __round__ method");
    if (args.size() == 1 || args[1].isNone())
        return x.is<double>() ? Value(roundToInt(x.as<double>())) : asInt(x);
    if (!isIntLike(args[1])) {
        throw EvalProblem("round(): '" + std::string(typeName(args[1])) +
                          "' object cannot be interpreted as an integer");
    }
    const std::int64_t ndigits = asInt(args[1]);
    if (x.is<double>())
        return roundFloatDigits(x.as<double>(), ndigits);
    return roundIntDigits(asInt(x), ndigits);
}

Value sortedValues(const Value& iterable, Budget& budget) {
    List items = iterate(iterable, "sorted()", budget);
    budget.step(items.size() * static_cast<std::size_t>(std::bit_width(items.size())));  // n log n
    std::stable_sort(items.begin(), items.end(),
                     [](const Value& a, const Value& b) { return pythonOrder(a, b, "<") < 0; });
    return items;
}

Value sumValues(const std::vector<Value>& args, Budget& budget) {
    Value total = args.size() > 1 ? args[1] : Value(0);
    if (total.is<std::string>())
        throw EvalProblem("sum() can't sum strings [use ''.join(seq) instead]");
    budget.takeCopy(total);
    for (const Value& item : iterate(args[0], "sum()", budget)) {
        budget.step();
        total = binaryOp(detail::BinaryOp::Add, total, item, budget);
    }
    return total;
}

bool anyAll(const Value& iterable, bool wantAll, Budget& budget) {
    for (const Value& item : iterate(iterable, wantAll ? "all()" : "any()", budget)) {
        budget.step();
        if (truthy(item) != wantAll)
            return !wantAll;
    }
    return wantAll;
}

// str(x): the text is counted once made (its length follows from x, which was counted).
Value strValue(const Args& args, Budget& budget) {
    if (args.empty())
        return Value("");
    std::string text = toPythonStr(args[0]);
    budget.take(text.size());
    return Value(std::move(text));
}

/// Every built-in in enum order: its name, argument count and implementation.
constexpr std::array<BuiltinInfo, 36> kBuiltins = {{
    {Builtin::Abs, "abs", 1, 1, [](const Args& a, Budget&) -> Value { return absValue(a[0]); }},
    {Builtin::All, "all", 1, 1, [](const Args& a, Budget& b) -> Value { return anyAll(a[0], true, b); }},
    {Builtin::Any, "any", 1, 1, [](const Args& a, Budget& b) -> Value { return anyAll(a[0], false, b); }},
    {Builtin::Bool, "bool", 0, 1, [](const Args& a, Budget&) -> Value { return !a.empty() && truthy(a[0]); }},
    {Builtin::Float, "float", 0, 1,
     [](const Args& a, Budget&) -> Value { return a.empty() ? Value(0.0) : toFloat(a[0]); }},
    {Builtin::Int, "int", 0, 1,
     [](const Args& a, Budget&) -> Value { return a.empty() ? Value(0) : toInt(a[0]); }},
    {Builtin::Len, "len", 1, 1, [](const Args& a, Budget&) -> Value { return length(a[0]); }},
    {Builtin::List, "list", 0, 1,
     [](const Args& a, Budget& b) -> Value {
         return a.empty() ? Value(List{}) : Value(iterate(a[0], "list()", b));
     }},
    {Builtin::Map, "map", 2, kVariadic, mapValues},
    {Builtin::Max, "max", 1, kVariadic,
     [](const Args& a, Budget& b) -> Value { return extreme(a, true, b); }},
    {Builtin::Min, "min", 1, kVariadic,
     [](const Args& a, Budget& b) -> Value { return extreme(a, false, b); }},
    {Builtin::Round, "round", 1, 2, [](const Args& a, Budget&) -> Value { return roundValue(a); }},
    {Builtin::Sorted, "sorted", 1, 1,
     [](const Args& a, Budget& b) -> Value { return sortedValues(a[0], b); }},
    {Builtin::Str, "str", 0, 1, strValue},
    {Builtin::Sum, "sum", 1, 2, sumValues},
    {Builtin::MathSqrt, "math.sqrt", 1, 1, nullptr},
    {Builtin::MathCeil, "math.ceil", 1, 1, nullptr},
    {Builtin::MathFloor, "math.floor", 1, 1, nullptr},
    {Builtin::MathTrunc, "math.trunc", 1, 1, nullptr},
    {Builtin::MathLog, "math.log", 1, 2, nullptr},
    {Builtin::MathLog10, "math.log10", 1, 1, nullptr},
    {Builtin::MathLog2, "math.log2", 1, 1, nullptr},
    {Builtin::MathExp, "math.exp", 1, 1, nullptr},
    {Builtin::MathSin, "math.sin", 1, 1, nullptr},
    {Builtin::MathCos, "math.cos", 1, 1, nullptr},
    {Builtin::MathTan, "math.tan", 1, 1, nullptr},
    {Builtin::MathAsin, "math.asin", 1, 1, nullptr},
    {Builtin::MathAcos, "math.acos", 1, 1, nullptr},
    {Builtin::MathAtan, "math.atan", 1, 1, nullptr},
    {Builtin::MathAtan2, "math.atan2", 2, 2, nullptr},
    {Builtin::MathRadians, "math.radians", 1, 1, nullptr},
    {Builtin::MathDegrees, "math.degrees", 1, 1, nullptr},
    {Builtin::MathFabs, "math.fabs", 1, 1, nullptr},
    {Builtin::MathPow, "math.pow", 2, 2, nullptr},
    {Builtin::MathIsclose, "math.isclose", 2, 2, nullptr},
    {Builtin::MathHypot, "math.hypot", 2, 2, nullptr},
}};

constexpr bool tableMatchesEnum() {
    for (std::size_t i = 0; i < kBuiltins.size(); ++i) {
        if (static_cast<std::size_t>(kBuiltins[i].id) != i)
            return false;
    }
    return true;
}
static_assert(tableMatchesEnum(), "kBuiltins must list the Builtin ids in enum order");

const BuiltinInfo& info(Builtin id) {
    return kBuiltins[static_cast<std::size_t>(id)];
}

}  // namespace

std::string_view builtinName(Builtin id) {
    return info(id).name;
}

std::optional<Builtin> findBuiltin(std::string_view name) {
    for (const BuiltinInfo& b : kBuiltins) {
        if (b.name == name)
            return b.id;
    }
    return std::nullopt;
}

std::optional<Value> findMathMember(std::string_view name) {
    if (name == "pi")
        return std::numbers::pi;
    if (name == "e")
        return std::numbers::e;
    if (name == "tau")
        return 2 * std::numbers::pi;
    if (name == "inf")
        return std::numeric_limits<double>::infinity();
    if (name == "nan")
        return std::numeric_limits<double>::quiet_NaN();
    const auto found = findBuiltin("math." + std::string(name));
    if (found)
        return Value(FunctionRef{*found});
    return std::nullopt;
}

Value callBuiltin(Builtin id, const std::vector<Value>& args, Budget& budget) {
    const BuiltinInfo& builtin = info(id);
    checkArgCount(builtin, args.size());
    return builtin.call ? builtin.call(args, budget) : callMathBuiltin(id, args);
}

}  // namespace mixengine::formula
