#include "gcode/format/ExtrusionAxis.h"

#include <cmath>

#include "gcode/format/NumberFormat.h"

namespace mixengine {

std::string formatUnits(long long units) {
    return formatExtrusion(static_cast<double>(units) / kUnitsPerAxisUnit);
}

void ExtrusionAxis::account(double delta) {
    if (delta < 0) {
        retracted_ += -delta;
    } else {
        const double prime = std::min(delta, retracted_);
        retracted_ -= prime;
        total_ += delta - prime;
    }
}

std::string ExtrusionAxis::move(double delta) {
    account(delta);
    std::string word(1, letter_);
    if (relative_) {
        // Write the delta between rounded positions so the sum of words equals the true total.
        position_ += delta;
        const double target = std::round(position_ * 1e5) / 1e5;
        appendDecimal(word, target - written_, 5);
        written_ = target;
        return word;
    }
    position_ += delta;
    appendDecimal(word, position_, 5);
    return word;
}

long long ExtrusionAxis::moveUnits(double delta) {
    account(delta);
    position_ += delta;
    const long long now = std::llround(position_ * kUnitsPerAxisUnit);
    const long long units = now - written_units_;
    written_units_ = now;
    return units;
}

std::string ExtrusionAxis::reset() {
    if (relative_)
        return "";
    position_ = 0;
    written_units_ = 0;
    return std::string("G92 ") + letter_ + "0";
}

}  // namespace mixengine
