#include "settings/formula/Numeric.h"

#include <cmath>
#include <limits>
#include <string>

#include "settings/formula/FormulaError.h"

namespace mixengine::formula {

namespace {

constexpr double kTwoPow63 = 9223372036854775808.0;

bool isOddInteger(double d) {
    return std::fmod(std::fabs(d), 2.0) == 1.0;
}

}  // namespace

std::int64_t asInt(const Value& v) {
    return v.is<bool>() ? (v.as<bool>() ? 1 : 0) : v.as<std::int64_t>();
}

double asDouble(const Value& v) {
    return v.is<double>() ? v.as<double>() : static_cast<double>(asInt(v));
}

std::partial_ordering compareIntDouble(std::int64_t i, double d) {
    if (std::isnan(d))
        return std::partial_ordering::unordered;
    if (d >= kTwoPow63)
        return std::partial_ordering::less;
    if (d < -kTwoPow63)
        return std::partial_ordering::greater;
    const double whole = std::trunc(d);
    const auto wholeInt = static_cast<std::int64_t>(whole);
    if (i != wholeInt)
        return i < wholeInt ? std::partial_ordering::less : std::partial_ordering::greater;
    const double fraction = d - whole;
    if (fraction > 0)
        return std::partial_ordering::less;
    if (fraction < 0)
        return std::partial_ordering::greater;
    return std::partial_ordering::equivalent;
}

Value addInt(std::int64_t a, std::int64_t b) {
    std::int64_t r = 0;
    if (__builtin_add_overflow(a, b, &r))
        return static_cast<double>(a) + static_cast<double>(b);
    return r;
}

Value subInt(std::int64_t a, std::int64_t b) {
    std::int64_t r = 0;
    if (__builtin_sub_overflow(a, b, &r))
        return static_cast<double>(a) - static_cast<double>(b);
    return r;
}

Value mulInt(std::int64_t a, std::int64_t b) {
    std::int64_t r = 0;
    if (__builtin_mul_overflow(a, b, &r))
        return static_cast<double>(a) * static_cast<double>(b);
    return r;
}

Value negInt(std::int64_t a) {
    if (a == std::numeric_limits<std::int64_t>::min())
        return -static_cast<double>(a);
    return -a;
}

Value floorDivInt(std::int64_t a, std::int64_t b) {
    if (b == 0)
        throw detail::EvalProblem("integer division or modulo by zero");
    if (a == std::numeric_limits<std::int64_t>::min() && b == -1)
        return -static_cast<double>(a);
    std::int64_t q = a / b;
    if ((a % b != 0) && ((a < 0) != (b < 0)))
        --q;
    return q;
}

std::int64_t modInt(std::int64_t a, std::int64_t b) {
    if (b == 0)
        throw detail::EvalProblem("integer division or modulo by zero");
    if (b == -1)
        return 0;
    std::int64_t r = a % b;
    if (r != 0 && ((r < 0) != (b < 0)))
        r += b;
    return r;
}

double floorDivFloat(double a, double b) {
    if (b == 0.0)
        throw detail::EvalProblem("float floor division by zero");
    double mod = std::fmod(a, b);
    double div = (a - mod) / b;
    if (mod != 0.0) {
        if ((b < 0) != (mod < 0))
            div -= 1.0;
    }
    if (div == 0.0)
        return std::copysign(0.0, a / b);
    double floored = std::floor(div);
    if (div - floored > 0.5)
        floored += 1.0;
    return floored;
}

double modFloat(double a, double b) {
    if (b == 0.0)
        throw detail::EvalProblem("float modulo by zero");
    double mod = std::fmod(a, b);
    if (mod != 0.0) {
        if ((b < 0) != (mod < 0))
            mod += b;
    } else {
        mod = std::copysign(0.0, b);
    }
    return mod;
}

double trueDivide(double a, double b) {
    if (b == 0.0)
        throw detail::EvalProblem("division by zero");
    return a / b;
}

double trueDivideInt(std::int64_t a, std::int64_t b) {
    constexpr std::int64_t kExact = std::int64_t{1} << 53;
    if (b == 0) {
        throw detail::EvalProblem("division by zero");
    }
    if (a <= kExact && a >= -kExact && b <= kExact && b >= -kExact) {
        return static_cast<double>(a) / static_cast<double>(b);
    }
    // Python rounds the exact quotient once; a wider intermediate comes closest without big ints.
    return static_cast<double>(static_cast<long double>(a) / static_cast<long double>(b));
}

Value powInt(std::int64_t base, std::int64_t exponent) {
    if (exponent < 0)
        return powFloat(static_cast<double>(base), static_cast<double>(exponent));
    std::int64_t result = 1;
    std::int64_t factor = base;
    for (std::int64_t e = exponent; e > 0; e >>= 1) {
        const bool overflows = ((e & 1) && __builtin_mul_overflow(result, factor, &result)) ||
                               ((e >> 1) > 0 && __builtin_mul_overflow(factor, factor, &factor));
        if (overflows) {
            return powFloat(static_cast<double>(base), static_cast<double>(exponent));
        }
    }
    return Value(result);
}

double powFloat(double base, double exponent) {
    // The special cases follow CPython's float_pow.
    if (exponent == 0.0)
        return 1.0;
    if (std::isnan(base))
        return base;
    if (std::isnan(exponent))
        return base == 1.0 ? 1.0 : exponent;
    if (std::isinf(exponent)) {
        const double magnitude = std::fabs(base);
        if (magnitude == 1.0)
            return 1.0;
        return ((exponent > 0) == (magnitude > 1.0)) ? std::fabs(exponent) : 0.0;
    }
    if (std::isinf(base)) {
        const bool odd = isOddInteger(exponent);
        if (exponent > 0)
            return odd ? base : std::fabs(base);
        return odd ? std::copysign(0.0, base) : 0.0;
    }
    if (base == 0.0) {
        if (exponent < 0)
            throw detail::EvalProblem("0.0 cannot be raised to a negative power");
        return isOddInteger(exponent) ? base : 0.0;
    }
    if (base < 0 && exponent != std::floor(exponent)) {
        throw detail::EvalProblem("negative number cannot be raised to a fractional power");
    }
    if (base == 1.0)
        return 1.0;
    const double result = std::pow(base, exponent);
    if (std::isinf(result))
        throw detail::EvalProblem("numerical result out of range in **");
    return result;
}

}  // namespace mixengine::formula
