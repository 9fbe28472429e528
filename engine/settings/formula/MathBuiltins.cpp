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

/// Where a one-argument math function is defined; outside, Python raises "math domain error". A
/// NaN is inside every domain (the function then returns NaN).
enum class Domain { Reals, Finite, NonNegative, Positive, UnitInterval };

bool outside(double x, Domain domain) {
    switch (domain) {
        case Domain::Finite:
            return std::isinf(x);
        case Domain::NonNegative:
            return x < 0;
        case Domain::Positive:
            return x <= 0;
        case Domain::UnitInterval:
            return x < -1.0 || x > 1.0;
        case Domain::Reals:
            break;
    }
    return false;
}

double logarithm(Builtin id, double x) {
    if (outside(x, Domain::Positive))
        domainError(id);
    return std::log(x);
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

/// A math function of one real argument, defined on `domain`.
struct UnaryEntry {
    Builtin id;
    double (*call)(double x);
    Domain domain;
};

constexpr std::array<UnaryEntry, 12> kUnaryFunctions = {{
    {Builtin::MathSqrt, [](double x) { return std::sqrt(x); }, Domain::NonNegative},
    {Builtin::MathLog10, [](double x) { return std::log10(x); }, Domain::Positive},
    {Builtin::MathLog2, [](double x) { return std::log2(x); }, Domain::Positive},
    {Builtin::MathSin, [](double x) { return std::sin(x); }, Domain::Finite},
    {Builtin::MathCos, [](double x) { return std::cos(x); }, Domain::Finite},
    {Builtin::MathTan, [](double x) { return std::tan(x); }, Domain::Finite},
    {Builtin::MathAsin, [](double x) { return std::asin(x); }, Domain::UnitInterval},
    {Builtin::MathAcos, [](double x) { return std::acos(x); }, Domain::UnitInterval},
    {Builtin::MathAtan, [](double x) { return std::atan(x); }, Domain::Reals},
    {Builtin::MathRadians, [](double x) { return x * kRadiansPerDegree; }, Domain::Reals},
    {Builtin::MathDegrees, [](double x) { return x * (180.0 / std::numbers::pi); }, Domain::Reals},
    {Builtin::MathFabs, [](double x) { return std::fabs(x); }, Domain::Reals},
}};

/// The other math functions of real arguments: log (1 or 2 arguments), exp (range error) and the
/// two-argument ones.
struct RealEntry {
    Builtin id;
    Value (*call)(Builtin id, const Reals& a);
};

constexpr std::array<RealEntry, 6> kRealFunctions = {{
    {Builtin::MathLog, mathLog},
    {Builtin::MathExp,
     [](Builtin id, const Reals& a) -> Value { return checkRange(id, std::exp(a.x), a.x); }},
    {Builtin::MathAtan2, [](Builtin, const Reals& a) -> Value { return std::atan2(a.x, a.y.value_or(0.0)); }},
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
    Reals a;
    a.x = realArg(id, args[0]);
    if (args.size() > 1)
        a.y = realArg(id, args[1]);
    if (const UnaryEntry* unary = findEntry(kUnaryFunctions, id)) {
        if (outside(a.x, unary->domain))
            domainError(id);
        return unary->call(a.x);
    }
    if (const RealEntry* real = findEntry(kRealFunctions, id))
        return real->call(id, a);
    throw detail::EvalProblem("internal: " + std::string(builtinName(id)) + " is not a math function");
}

}  // namespace mixengine::formula
