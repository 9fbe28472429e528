#include "gcode/format/NumberFormat.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>

namespace mixengine {
namespace {

constexpr double kPowersOfTen[] = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8};
constexpr std::uint64_t kIntegerPowersOfTen[] = {1,      10,      100,      1000,     10000,
                                                 100000, 1000000, 10000000, 100000000};

/// `magnitude` × 10^decimals rounded as printf rounds the exact binary value, when the double
/// product decides it: its fraction lies clearly off .5 (farther than the product's own rounding
/// error, at most half an ulp). Nothing when the product is too large or the fraction too close to call.
std::optional<std::uint64_t> scaledWhenClear(double magnitude, int decimals) {
    const double scaled = magnitude * kPowersOfTen[decimals];
    if (!(scaled < 1e15))
        return std::nullopt;
    const double whole = std::floor(scaled);
    const double fraction = scaled - whole;  // exact
    const double error = scaled * 0x1p-52;   // twice the product's largest rounding error
    if (std::fabs(fraction - 0.5) <= error)
        return std::nullopt;
    return static_cast<std::uint64_t>(whole) + (fraction > 0.5 ? 1 : 0);
}

/// Appends `units` (the value × 10^decimals, rounded) as a decimal with at most `decimals` decimals,
/// no trailing zeros, "0" for zero.
void appendUnits(std::string& out, bool negative, std::uint64_t units, int decimals) {
    if (units == 0) {
        out += '0';
        return;
    }
    char buffer[32];
    char* const end = buffer + sizeof buffer;
    char* begin = end;
    std::uint64_t fraction = units % kIntegerPowersOfTen[decimals];
    int fraction_digits = decimals;
    while (fraction_digits > 0 && fraction % 10 == 0) {  // trailing zeros dropped
        fraction /= 10;
        --fraction_digits;
    }
    for (int i = 0; i < fraction_digits; ++i, fraction /= 10)
        *--begin = static_cast<char>('0' + fraction % 10);
    if (fraction_digits > 0)
        *--begin = '.';
    std::uint64_t whole = units / kIntegerPowersOfTen[decimals];
    do {
        *--begin = static_cast<char>('0' + whole % 10);
        whole /= 10;
    } while (whole > 0);
    if (negative)
        *--begin = '-';
    out.append(begin, end);
}

/// Appends the text of `value` with at most `decimals` decimals, rounded from its exact binary value
/// as printf's "%.*f" rounds it (CuraEngine 4.13 writes with printf: 2.55, stored as 2.5499…, is
/// "2.5"), no trailing zeros, no "-0"; no locale. The integer path (scaledWhenClear) serves almost
/// every number; std::to_chars decides the rest.
void appendScaled(std::string& out, double value, int decimals) {
    if (const std::optional<std::uint64_t> units = scaledWhenClear(std::fabs(value), decimals)) {
        appendUnits(out, value < 0, *units, decimals);
        return;
    }
    char buffer[64];
    char* end = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed, decimals).ptr;
    if (decimals > 0) {
        while (end[-1] == '0')
            --end;
        if (end[-1] == '.')
            --end;
    }
    const bool negative_zero = buffer[0] == '-' && end - buffer == 2 && buffer[1] == '0';
    if (negative_zero)
        out += '0';
    else
        out.append(buffer, end);
}

}  // namespace

void appendDecimal(std::string& out, double value, int decimals) {
    if (decimals >= 0 && decimals <= 8 && std::fabs(value) < 9e9)
        appendScaled(out, value, decimals);
    else
        out += formatDecimal(value, decimals);
}

void appendMicronsAsMm(std::string& out, std::int64_t microns) {
    const bool negative = microns < 0;
    appendUnits(out, negative,
                negative ? 0 - static_cast<std::uint64_t>(microns) : static_cast<std::uint64_t>(microns), 3);
}

std::string formatDecimal(double value, int decimals) {
    if (decimals >= 0 && decimals <= 8 && std::fabs(value) < 9e9) {
        std::string text;
        appendScaled(text, value, decimals);
        return text;
    }
    const double scale = std::pow(10.0, decimals);
    double rounded = std::round(value * scale) / scale;
    if (rounded == 0.0)
        rounded = 0.0;  // turns -0 into 0
    char buffer[400];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, rounded);
    std::string text(buffer);
    if (text.find('.') != std::string::npos) {
        while (text.back() == '0')
            text.pop_back();
        if (text.back() == '.')
            text.pop_back();
    }
    if (text == "-0")
        text = "0";
    return text;
}

std::string formatFeedrate(double mm_per_s) {
    return formatDecimal(mm_per_s * 60.0, 1);
}

}  // namespace mixengine
