// The functions of Python's math module, with its domain and range errors.
#include <cmath>
#include <numbers>
#include <string>

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

double logarithm(Builtin id, double x) {
    if (x <= 0)
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

}  // namespace

Value callMathBuiltin(Builtin id, const std::vector<Value>& args) {
    switch (id) {
        case Builtin::MathCeil:
            return integral(id, args[0], [](double d) { return std::ceil(d); });
        case Builtin::MathFloor:
            return integral(id, args[0], [](double d) { return std::floor(d); });
        case Builtin::MathTrunc:
            return integral(id, args[0], [](double d) { return std::trunc(d); });
        default:
            break;
    }
    const double x = realArg(id, args[0]);
    const double y = args.size() > 1 ? realArg(id, args[1]) : 0.0;
    switch (id) {
        case Builtin::MathSqrt:
            if (x < 0)
                domainError(id);
            return std::sqrt(x);
        case Builtin::MathLog: {
            const double lnx = logarithm(id, x);
            if (args.size() == 1)
                return lnx;
            const double lnBase = logarithm(id, y);
            if (lnBase == 0.0)
                throw EvalProblem("math.log(): float division by zero");
            return lnx / lnBase;
        }
        case Builtin::MathLog10:
            if (x <= 0)
                domainError(id);
            return std::log10(x);
        case Builtin::MathLog2:
            if (x <= 0)
                domainError(id);
            return std::log2(x);
        case Builtin::MathExp:
            return checkRange(id, std::exp(x), x);
        case Builtin::MathSin:
            return trigonometric(id, x, [](double d) { return std::sin(d); });
        case Builtin::MathCos:
            return trigonometric(id, x, [](double d) { return std::cos(d); });
        case Builtin::MathTan:
            return trigonometric(id, x, [](double d) { return std::tan(d); });
        case Builtin::MathAsin:
            return inverseTrigonometric(id, x, [](double d) { return std::asin(d); });
        case Builtin::MathAcos:
            return inverseTrigonometric(id, x, [](double d) { return std::acos(d); });
        case Builtin::MathAtan:
            return std::atan(x);
        case Builtin::MathAtan2:
            return std::atan2(x, y);
        case Builtin::MathRadians:
            return x * (std::numbers::pi / 180.0);
        case Builtin::MathDegrees:
            return x * (180.0 / std::numbers::pi);
        case Builtin::MathFabs:
            return std::fabs(x);
        case Builtin::MathPow:
            return mathPow(id, x, y);
        case Builtin::MathIsclose:
            return isclose(x, y);
        case Builtin::MathHypot:
            return std::hypot(x, y);
        default:
            break;
    }
    throw detail::EvalProblem("internal: " + std::string(builtinName(id)) + " is not a math function");
}

}  // namespace mixengine::formula
