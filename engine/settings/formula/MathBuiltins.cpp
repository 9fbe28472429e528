// The functions of Python's math module, with its domain and range errors.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include "geometry/Angles.h"
#include "settings/formula/Builtins.h"
#include "settings/formula/FormulaError.h"
#include "settings/formula/Numeric.h"

namespace mixengine::formula {

namespace {

using detail::EvalProblem;

[[noreturn]] void domainError(Builtin id) {
    throw EvalProblem(std::string(builtinName(id)) + "(): math domain error");
}

double realArg(Builtin id, const Value& v) {
    if (!v.isNumber()) {
        throw EvalProblem(std::string(builtinName(id)) + "(): must be real number, not " +
                          std::string(typeName(v)));
    }
    return asDouble(v);
}

// A result computed from finite arguments must be finite, else Python raises OverflowError.
double checkRange(Builtin id, double result, double argument) {
    if (std::isinf(result) && std::isfinite(argument)) {
        throw EvalProblem(std::string(builtinName(id)) + "(): math range error");
    }
    return result;
}

// math.ceil / floor / trunc: ints stay as they are, floats become ints.
Value integral(Builtin id, const Value& v, double (*rounding)(double)) {
    if (v.is<bool>() || v.is<std::int64_t>())
        return asInt(v);
    return truncToInt(rounding(realArg(id, v)));
}

/// x, unless x <= 0 (or a NaN compares so): a math domain error.
double positive(Builtin id, double x) {
    if (x <= 0)
        domainError(id);
    return x;
}

double nonNegative(Builtin id, double x) {
    if (x < 0)
        domainError(id);
    return x;
}

double logarithm(Builtin id, double x) {
    return std::log(positive(id, x));
}

double mathPow(Builtin id, double x, double y) {
    if (x == 0.0 && y < 0 && std::isfinite(y))
        domainError(id);
    if (x < 0 && std::isfinite(x) && std::isfinite(y) && y != std::floor(y))
        domainError(id);
    const double result = std::pow(x, y);
    if (std::isinf(result) && std::isfinite(x) && std::isfinite(y)) {
        throw EvalProblem("math.pow(): math range error");
    }
    return result;
}

bool isclose(double a, double b) {
    constexpr double kRelTol = 1e-9;
    if (a == b)
        return true;
    if (std::isinf(a) || std::isinf(b))
        return false;
    const double diff = std::fabs(b - a);
    return diff <= std::fabs(kRelTol * b) || diff <= std::fabs(kRelTol * a);
}

double trigonometric(Builtin id, double x, double (*f)(double)) {
    if (std::isinf(x))
        domainError(id);
    return f(x);
}

double inverseTrigonometric(Builtin id, double x, double (*f)(double)) {
    if (x < -1.0 || x > 1.0)
        domainError(id);
    return f(x);
}

/// The real arguments of a math function: x, and y when it was given a second argument.
struct Reals {
    double x = 0;
    std::optional<double> y;
};

/// math.log(x) or math.log(x, base).
Value mathLog(Builtin id, const Reals& a) {
    const double lnx = logarithm(id, a.x);
    if (!a.y)
        return lnx;
    const double lnBase = logarithm(id, *a.y);
    if (lnBase == 0.0)
        throw EvalProblem("math.log(): float division by zero");
    return lnx / lnBase;
}

using RealFunction = Value (*)(Builtin id, const Reals& a);

struct RealEntry {
    Builtin id;
    RealFunction call;
};

/// The math functions of real arguments (all but ceil, floor and trunc). A missing y reads as 0.
constexpr std::array<RealEntry, 18> kRealFunctions = {{
    {Builtin::MathSqrt, [](Builtin id, const Reals& a) -> Value { return std::sqrt(nonNegative(id, a.x)); }},
    {Builtin::MathLog, mathLog},
    {Builtin::MathLog10, [](Builtin id, const Reals& a) -> Value { return std::log10(positive(id, a.x)); }},
    {Builtin::MathLog2, [](Builtin id, const Reals& a) -> Value { return std::log2(positive(id, a.x)); }},
    {Builtin::MathExp,
     [](Builtin id, const Reals& a) -> Value { return checkRange(id, std::exp(a.x), a.x); }},
    {Builtin::MathSin,
     [](Builtin id, const Reals& a) -> Value {
         return trigonometric(id, a.x, [](double d) { return std::sin(d); });
     }},
    {Builtin::MathCos,
     [](Builtin id, const Reals& a) -> Value {
         return trigonometric(id, a.x, [](double d) { return std::cos(d); });
     }},
    {Builtin::MathTan,
     [](Builtin id, const Reals& a) -> Value {
         return trigonometric(id, a.x, [](double d) { return std::tan(d); });
     }},
    {Builtin::MathAsin,
     [](Builtin id, const Reals& a) -> Value {
         return inverseTrigonometric(id, a.x, [](double d) { return std::asin(d); });
     }},
    {Builtin::MathAcos,
     [](Builtin id, const Reals& a) -> Value {
         return inverseTrigonometric(id, a.x, [](double d) { return std::acos(d); });
     }},
    {Builtin::MathAtan, [](Builtin, const Reals& a) -> Value { return std::atan(a.x); }},
    {Builtin::MathAtan2, [](Builtin, const Reals& a) -> Value { return std::atan2(a.x, a.y.value_or(0.0)); }},
    {Builtin::MathRadians, [](Builtin, const Reals& a) -> Value { return a.x * kRadiansPerDegree; }},
    {Builtin::MathDegrees, [](Builtin, const Reals& a) -> Value { return a.x * (180.0 / std::numbers::pi); }},
    {Builtin::MathFabs, [](Builtin, const Reals& a) -> Value { return std::fabs(a.x); }},
    {Builtin::MathPow,
     [](Builtin id, const Reals& a) -> Value { return mathPow(id, a.x, a.y.value_or(0.0)); }},
    {Builtin::MathIsclose, [](Builtin, const Reals& a) -> Value { return isclose(a.x, a.y.value_or(0.0)); }},
    {Builtin::MathHypot, [](Builtin, const Reals& a) -> Value { return std::hypot(a.x, a.y.value_or(0.0)); }},
}};

/// math.ceil / floor / trunc: the rounding each applies to a float.
struct IntegralEntry {
    Builtin id;
    double (*rounding)(double);
};

constexpr std::array<IntegralEntry, 3> kIntegralFunctions = {{
    {Builtin::MathCeil, [](double d) { return std::ceil(d); }},
    {Builtin::MathFloor, [](double d) { return std::floor(d); }},
    {Builtin::MathTrunc, [](double d) { return std::trunc(d); }},
}};

template <class Entry, std::size_t N>
const Entry* findEntry(const std::array<Entry, N>& table, Builtin id) {
    const auto it = std::find_if(table.begin(), table.end(), [id](const Entry& e) { return e.id == id; });
    return it == table.end() ? nullptr : &*it;
}

}  // namespace

Value callMathBuiltin(Builtin id, const std::vector<Value>& args) {
    if (const IntegralEntry* integralEntry = findEntry(kIntegralFunctions, id))
        return integral(id, args[0], integralEntry->rounding);
    const RealEntry* real = findEntry(kRealFunctions, id);
    if (!real)
        throw detail::EvalProblem("internal: " + std::string(builtinName(id)) + " is not a math function");
    Reals a;
    a.x = realArg(id, args[0]);
    if (args.size() > 1)
        a.y = realArg(id, args[1]);
    return real->call(id, a);
}

}  // namespace mixengine::formula
