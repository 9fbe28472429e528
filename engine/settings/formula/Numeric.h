#pragma once
// Python's numeric rules on int64 and double, internal to the formula code. Every function throws
// detail::EvalProblem where Python raises (ZeroDivisionError, ValueError, OverflowError).
//
// Python ints are unbounded; here they are int64. Integer arithmetic whose exact result does not
// fit (e.g. 299792458000 ** 2, which Cura's definitions compute) continues in floating point and
// returns a float; conversions that must return an int (int(), round(), math.ceil) throw instead.
#include <compare>
#include <cstdint>
#include <string_view>

#include "settings/formula/Value.h"

namespace mixengine::formula {

/// A bool or int as int64; precondition: v is bool or int.
std::int64_t asInt(const Value& v);
/// A bool, int or float as double; precondition: v.isNumber().
double asDouble(const Value& v);

/// Exact comparison of an int with a double (no rounding of the int); unordered for NaN.
std::partial_ordering compareIntDouble(std::int64_t i, double d);

/// a + b, a - b, a * b, -a on ints: an int, or a float if the result does not fit in int64.
Value addInt(std::int64_t a, std::int64_t b);
Value subInt(std::int64_t a, std::int64_t b);
Value mulInt(std::int64_t a, std::int64_t b);
Value negInt(std::int64_t a);

/// `a // b` and `a % b` for ints: floored, the remainder takes the sign of b.
Value floorDivInt(std::int64_t a, std::int64_t b);
std::int64_t modInt(std::int64_t a, std::int64_t b);
/// `a // b` and `a % b` for floats, as CPython's float_floor_div / float_mod.
double floorDivFloat(double a, double b);
double modFloat(double a, double b);
double trueDivide(double a, double b);
/// `a / b` for ints: exact when both fit in a double's 53 bits, else via long double.
double trueDivideInt(std::int64_t a, std::int64_t b);

/// `a ** b`: int for a non-negative int exponent (float if it does not fit), float otherwise.
/// Python 3 would return a complex number for a negative base and a fractional exponent: an error.
Value powInt(std::int64_t base, std::int64_t exponent);
double powFloat(double base, double exponent);

/// int(d): truncation toward zero; errors for NaN, infinities and values outside int64.
std::int64_t truncToInt(double d);
/// round(d): to the nearest int, ties to even.
std::int64_t roundToInt(double d);
/// round(d, n): the double nearest to d rounded to n decimals, ties to even on d's exact value.
double roundFloatDigits(double d, std::int64_t ndigits);
/// round(i, n): for n < 0 rounds to a multiple of 10**-n, ties to even.
std::int64_t roundIntDigits(std::int64_t i, std::int64_t ndigits);

/// int("..."): optional whitespace and sign, decimal digits with single underscores between them.
std::int64_t parseIntString(std::string_view text);
/// float("..."): as Python, including "inf", "-infinity", "nan", "1e3", " 2.5 ".
double parseFloatString(std::string_view text);

}  // namespace mixengine::formula
