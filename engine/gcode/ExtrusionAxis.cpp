#include "gcode/ExtrusionAxis.h"

#include <cmath>

#include "gcode/NumberFormat.h"

namespace mixengine {

std::string formatUnits(long long units) {
    return formatExtrusionMm(static_cast<double>(units) / kUnitsPerMm);
}

void ExtrusionAxis::account(double delta_mm) {
    if (delta_mm < 0) {
        retracted_mm_ += -delta_mm;
    } else {
        const double prime = std::min(delta_mm, retracted_mm_);
        retracted_mm_ -= prime;
        total_mm_ += delta_mm - prime;
    }
}

std::string ExtrusionAxis::move(double delta_mm) {
    account(delta_mm);
    std::string word(1, letter_);
    if (relative_) {
        // Write the delta between rounded positions so the sum of words equals the true total.
        position_mm_ += delta_mm;
        const double target = std::round(position_mm_ * 1e5) / 1e5;
        word += formatExtrusionMm(target - written_mm_);
        written_mm_ = target;
        return word;
    }
    position_mm_ += delta_mm;
    word += formatExtrusionMm(position_mm_);
    return word;
}

long long ExtrusionAxis::moveUnits(double delta_mm) {
    account(delta_mm);
    position_mm_ += delta_mm;
    const long long now = std::llround(position_mm_ * kUnitsPerMm);
    const long long units = now - written_units_;
    written_units_ = now;
    return units;
}

std::string ExtrusionAxis::reset() {
    if (relative_)
        return "";
    position_mm_ = 0;
    written_units_ = 0;
    return std::string("G92 ") + letter_ + "0";
}

}  // namespace mixengine
