#include "gcode/NumberFormat.h"

#include <cmath>
#include <cstdio>

namespace mixengine {

std::string formatDecimal(double value, int decimals) {
    const double scale = std::pow(10.0, decimals);
    double rounded = std::round(value * scale) / scale;
    if (rounded == 0.0)
        rounded = 0.0;  // turns -0 into 0
    char buffer[64];
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
