// Conversions between floats, ints and strings with Python's rules: int(), round(), float("...").
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>
#include <system_error>

#include "settings/formula/FormulaError.h"
#include "settings/formula/Numeric.h"

namespace mixengine::formula {

namespace {

constexpr double kTwoPow63 = 9223372036854775808.0;
// Beyond these ndigits CPython's round() returns x unchanged, or a zero of x's sign.
constexpr std::int64_t kMaxDigits = 323;
constexpr std::int64_t kMinDigits = -308;

std::int64_t checkedDoubleToInt(double d) {
    if (std::isnan(d))
        throw detail::EvalProblem("cannot convert float NaN to integer");
    if (std::isinf(d))
        throw detail::EvalProblem("cannot convert float infinity to integer");
    if (d >= kTwoPow63 || d < -kTwoPow63) {
        throw detail::EvalProblem("integer overflow: " + floatRepr(d) + " does not fit in 64 bits");
    }
    return static_cast<std::int64_t>(d);
}

std::string_view stripSpace(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front())))
        s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back())))
        s.remove_suffix(1);
    return s;
}

// Removes underscores that sit between two digits; false if any underscore is elsewhere.
bool removeDigitUnderscores(std::string_view in, std::string& out) {
    out.clear();
    for (std::size_t i = 0; i < in.size(); ++i) {
        if (in[i] != '_') {
            out += in[i];
            continue;
        }
        const bool between = i > 0 && i + 1 < in.size() &&
                             std::isdigit(static_cast<unsigned char>(in[i - 1])) &&
                             std::isdigit(static_cast<unsigned char>(in[i + 1]));
        if (!between)
            return false;
    }
    return true;
}

bool isDecimalFloat(std::string_view s) {
    std::size_t i = 0;
    std::size_t mantissaDigits = 0;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) {
        ++i;
        ++mantissaDigits;
    }
    if (i < s.size() && s[i] == '.') {
        ++i;
        while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) {
            ++i;
            ++mantissaDigits;
        }
    }
    if (mantissaDigits == 0)
        return false;
    if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
        ++i;
        if (i < s.size() && (s[i] == '+' || s[i] == '-'))
            ++i;
        const std::size_t expStart = i;
        while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i])))
            ++i;
        if (i == expStart)
            return false;
    }
    return i == s.size();
}

bool equalsIgnoreCase(std::string_view a, std::string_view b) {
    if (a.size() != b.size())
        return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (std::tolower(static_cast<unsigned char>(a[i])) != b[i])
            return false;
    }
    return true;
}

// Whether a decimal literal that from_chars found out of range is huge (else it is tiny).
bool literalOverflows(std::string_view s) {
    long exponent = 0;
    const std::size_t e = s.find_first_of("eE");
    // strtol saturates at LONG_MAX on a huge exponent; clamped so that the sum below cannot overflow.
    if (e != std::string_view::npos)
        exponent = std::clamp(std::strtol(std::string(s.substr(e + 1)).c_str(), nullptr, 10), -1000000000L,
                              1000000000L);
    const std::string_view mantissa = s.substr(0, e);
    const std::size_t point = std::min(mantissa.find('.'), mantissa.size());
    const std::size_t firstNonZero = mantissa.find_first_of("123456789");
    const long position = firstNonZero < point ? static_cast<long>(point - firstNonZero)
                                               : -static_cast<long>(firstNonZero - point) + 1;
    return position + exponent > 0;
}

// Increments a string of decimal digits by one unit in its last place.
void incrementDigits(std::string& digits) {
    std::size_t i = digits.size();
    while (i > 0) {
        --i;
        if (digits[i] != '9') {
            ++digits[i];
            return;
        }
        digits[i] = '0';
    }
    digits.insert(digits.begin(), '1');
}

}  // namespace

std::int64_t truncToInt(double d) {
    return checkedDoubleToInt(std::trunc(d));
}

std::int64_t roundToInt(double d) {
    double r = std::round(d);
    if (std::fabs(d - r) == 0.5)
        r = 2.0 * std::round(d / 2.0);
    return checkedDoubleToInt(r);
}

double roundFloatDigits(double d, std::int64_t ndigits) {
    if (ndigits > kMaxDigits || !std::isfinite(d) || d == 0.0)
        return d;
    if (ndigits < kMinDigits)
        return 0.0 * d;
    // The exact decimal expansion of |d| (a double has at most 1074 fractional digits).
    char buf[1500];
    const auto res = std::to_chars(buf, buf + sizeof buf, std::fabs(d), std::chars_format::fixed, 1100);
    const std::string_view exact(buf, static_cast<std::size_t>(res.ptr - buf));
    const std::size_t point = exact.find('.');
    std::string integerPart(exact.substr(0, point));
    const std::string_view fraction = exact.substr(point + 1);
    // Pad so that at least one digit is kept left of the rounding position.
    if (ndigits < 0 && static_cast<std::int64_t>(integerPart.size()) <= -ndigits) {
        integerPart.insert(
            0, static_cast<std::size_t>(-ndigits - static_cast<std::int64_t>(integerPart.size()) + 1), '0');
    }
    const std::string all = integerPart + std::string(fraction);
    const auto keep = static_cast<std::size_t>(static_cast<std::int64_t>(integerPart.size()) + ndigits);
    std::string kept = all.substr(0, keep);
    const std::string_view rest = std::string_view(all).substr(keep);
    const bool aboveHalf =
        rest[0] > '5' || (rest[0] == '5' && rest.find_first_not_of('0', 1) != std::string::npos);
    const bool tie = rest[0] == '5' && !aboveHalf;
    if (aboveHalf || (tie && (kept.back() - '0') % 2 == 1))
        incrementDigits(kept);
    std::string text = d < 0 ? "-" : "";
    if (ndigits >= 0) {
        const std::size_t intDigits = kept.size() - static_cast<std::size_t>(ndigits);
        text += kept.substr(0, intDigits) + "." + kept.substr(intDigits) + "0";
    } else {
        text += kept + std::string(static_cast<std::size_t>(-ndigits), '0');
    }
    double result = 0.0;
    const auto parsed = std::from_chars(text.data(), text.data() + text.size(), result);
    if (parsed.ec == std::errc::result_out_of_range || std::isinf(result)) {
        throw detail::EvalProblem("rounded value too large to represent");
    }
    return result;
}

std::int64_t roundIntDigits(std::int64_t i, std::int64_t ndigits) {
    if (ndigits >= 0)
        return i;
    constexpr std::int64_t kFiveE18 = 5'000'000'000'000'000'000;
    if (ndigits < -19)
        return 0;          // |i| < 9.3e18 is below half of 10**20
    if (ndigits == -19) {  // half of 10**19 is 5e18; a tie rounds to the even multiple, 0
        if (i > kFiveE18 || i < -kFiveE18) {
            throw detail::EvalProblem("integer overflow in round() (the result does not fit in 64 bits)");
        }
        return 0;
    }
    std::int64_t unit = 1;
    for (std::int64_t k = 0; k < -ndigits; ++k)
        unit *= 10;
    std::int64_t quotient = floorDivInt(i, unit).as<std::int64_t>();  // unit > 1: no overflow
    const std::int64_t remainder = modInt(i, unit);                   // in [0, unit)
    if (2 * remainder > unit || (2 * remainder == unit && quotient % 2 != 0))
        ++quotient;
    std::int64_t result = 0;
    if (__builtin_mul_overflow(quotient, unit, &result)) {
        throw detail::EvalProblem("integer overflow in round() (the result does not fit in 64 bits)");
    }
    return result;
}

std::int64_t parseIntString(std::string_view text) {
    const auto invalid = [&] {
        return detail::EvalProblem("invalid literal for int() with base 10: " + toPythonRepr(Value(text)));
    };
    std::string_view s = stripSpace(text);
    bool negative = false;
    if (!s.empty() && (s[0] == '+' || s[0] == '-')) {
        negative = s[0] == '-';
        s.remove_prefix(1);
    }
    std::string digits;
    if (s.empty() || !removeDigitUnderscores(s, digits) ||
        digits.find_first_not_of("0123456789") != std::string::npos) {
        throw invalid();
    }
    if (negative)
        digits.insert(0, "-");
    std::int64_t value = 0;
    const auto parsed = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (parsed.ec == std::errc::result_out_of_range) {
        throw detail::EvalProblem("integer overflow in int(): " + std::string(text) +
                                  " does not fit in 64 bits");
    }
    return value;
}

double parseFloatString(std::string_view text) {
    std::string_view s = stripSpace(text);
    double sign = 1.0;
    if (!s.empty() && (s[0] == '+' || s[0] == '-')) {
        sign = s[0] == '-' ? -1.0 : 1.0;
        s.remove_prefix(1);
    }
    if (equalsIgnoreCase(s, "inf") || equalsIgnoreCase(s, "infinity")) {
        return sign * std::numeric_limits<double>::infinity();
    }
    if (equalsIgnoreCase(s, "nan"))
        return std::copysign(std::numeric_limits<double>::quiet_NaN(), sign);
    std::string plain;
    if (!removeDigitUnderscores(s, plain) || !isDecimalFloat(plain)) {
        throw detail::EvalProblem("could not convert string to float: " + toPythonRepr(Value(text)));
    }
    double value = 0.0;
    const auto parsed = std::from_chars(plain.data(), plain.data() + plain.size(), value);
    if (parsed.ec == std::errc::result_out_of_range) {
        value = literalOverflows(plain) ? std::numeric_limits<double>::infinity() : 0.0;
    }
    return sign * value;
}

}  // namespace mixengine::formula
