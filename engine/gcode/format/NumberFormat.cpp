#include "gcode/format/NumberFormat.h"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace mixengine {
namespace {

constexpr long long kPow10[] = {1, 10, 100, 1000, 10000, 100000, 1000000, 10000000, 100000000};

/// Appends the text of `value` with at most `decimals` decimals (rounded half away from zero), no
/// trailing zeros, no "-0"; integer arithmetic, so no locale and no printf.
void appendScaled(std::string& out, double value, int decimals) {
    const long long scale = kPow10[decimals];
    const long long scaled = std::llround(value * static_cast<double>(scale));
    const bool negative = scaled < 0;
    const unsigned long long magnitude =
        negative ? 0ULL - static_cast<unsigned long long>(scaled) : static_cast<unsigned long long>(scaled);
    char buffer[48];
    char* p = buffer;
    if (negative && magnitude != 0)
        *p++ = '-';
    p = std::to_chars(p, buffer + sizeof buffer, magnitude / static_cast<unsigned long long>(scale)).ptr;
    unsigned long long fraction = magnitude % static_cast<unsigned long long>(scale);
    if (fraction != 0) {
        int digits = decimals;
        while (fraction % 10 == 0)
            fraction /= 10, --digits;
        *p++ = '.';
        char tail[16];
        char* end = std::to_chars(tail, tail + sizeof tail, fraction).ptr;
        for (int pad = digits - static_cast<int>(end - tail); pad > 0; --pad)
            *p++ = '0';
        for (char* q = tail; q != end; ++q)
            *p++ = *q;
    }
    out.append(buffer, p);
}

}  // namespace

void appendDecimal(std::string& out, double value, int decimals) {
    if (decimals >= 0 && decimals <= 8 && std::fabs(value) < 9e9)
        appendScaled(out, value, decimals);
    else
        out += formatDecimal(value, decimals);
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
