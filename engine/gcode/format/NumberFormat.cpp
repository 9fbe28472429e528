#include "gcode/format/NumberFormat.h"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace mixengine {
namespace {

/// Appends the text of `value` with at most `decimals` decimals, rounded from its exact binary value
/// as printf's "%.*f" rounds it (CuraEngine 4.13 writes with printf: 2.55, stored as 2.5499…, is
/// "2.5"), no trailing zeros, no "-0"; std::to_chars, so no locale.
void appendScaled(std::string& out, double value, int decimals) {
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
