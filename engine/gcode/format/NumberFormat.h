#pragma once
// Compact number formatting for G-code: fixed decimals, trailing zeros and a trailing point
// removed, never "-0". XYZ use 3 decimals, E uses 5 (as CuraEngine and PrusaSlicer do).
// Extrusion values are in the axis unit: mm of filament, or mm³ of material when volumetric.
#include <cstdint>
#include <string>

namespace mixengine {

std::string formatDecimal(double value, int decimals);
/// formatDecimal(value, decimals) appended to `out` (the writer's hot path: no string of its own).
void appendDecimal(std::string& out, double value, int decimals);
/// `microns` as millimetres with 3 decimals: the text appendDecimal(out, microns / 1000.0, 3) gives
/// (that division rounds to the micron exactly), written from the integer (the writer's X, Y and Z).
void appendMicronsAsMm(std::string& out, std::int64_t microns);
inline std::string formatCoordMm(double mm) {
    return formatDecimal(mm, 3);
}
inline std::string formatExtrusion(double amount) {
    return formatDecimal(amount, 5);
}
/// Feedrate in mm/min from mm/s, at most one decimal ("F1500", "F1687.5").
std::string formatFeedrate(double mm_per_s);
inline void appendFeedrate(std::string& out, double mm_per_s) {
    appendDecimal(out, mm_per_s * 60.0, 1);
}

}  // namespace mixengine
