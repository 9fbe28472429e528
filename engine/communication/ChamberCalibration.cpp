#include "communication/ChamberCalibration.h"

#include <cmath>
#include <cstdarg>
#include <cstdio>

namespace mixengine {
namespace {

/// printf into a std::string (the guide's numbers, fixed decimals).
std::string format(const char* pattern, ...) __attribute__((format(printf, 1, 2)));
std::string format(const char* pattern, ...) {
    char buffer[512];
    va_list args;
    va_start(args, pattern);
    std::vsnprintf(buffer, sizeof buffer, pattern, args);
    va_end(args);
    return buffer;
}

/// The share of B leaving the nozzle after `volume_mm3` of B pushed into a chamber full of A.
double outletShare(const ChamberSpec& spec, double volume_mm3) {
    Chamber chamber(spec, MixVector::only(0, 2));
    chamber.push(MixVector::only(1, 2), volume_mm3);
    return chamber.outlet()[1];
}

/// "  12.34" or "  >15.0" when the height lies beyond the band the tower holds.
std::string heightCell(double height_mm, double band_mm) {
    if (height_mm > band_mm)
        return format("  >%4.1f", band_mm);
    return format("  %5.2f", height_mm);
}

void addHeader(const CalibrationTower& t, std::vector<std::string>& lines) {
    lines.push_back(format("Chamber calibration tower: %g x %g mm, one wall (spiralize), %g mm tall.",
                           t.side_mm, t.side_mm, t.height_mm));
    lines.push_back(format("  %s up to %.2f mm, %s from %.2f to %.2f mm, the first again above.",
                           t.filament_a.c_str(), t.switch1_mm, t.filament_b.c_str(), t.switch1_mm,
                           t.switch2_mm));
    lines.push_back("  Heights above the build plate. mixing_chamber_volume is 0 for this print: the G-code");
    lines.push_back("  switches at once at these heights, so the blur on the tower is the chamber's own.");
    lines.push_back(
        format("  Extrusion per mm of tower height: %.2f mm3/mm (from the sliced paths).", t.per_mm_mm3));
    lines.push_back(
        format("  The print: %.0f mm3 of filament, %.0f min.", t.filament_mm3, t.print_time_s / 60.0));
}

void addHowTo(const CalibrationTower& t, std::vector<std::string>& lines) {
    lines.push_back("How to read it:");
    lines.push_back("  1. At each switch measure how far above it the colour starts to change (10 % of the");
    lines.push_back("     way to the new filament) and where it stops changing (90 %). Judge the share, not");
    lines.push_back("     the brightness: a little of a dark filament shows strongly in a light one.");
    lines.push_back("  2. The stage count N follows from their ratio alone (column 90/10 below); then");
    lines.push_back(format("     V = (90 %% height) x %.2f / (that N's 90 %% factor).", t.per_mm_mm3));
    lines.push_back(
        "  3. Or take the row of the table nearest to both heights. Set mixing_chamber_volume = V");
    lines.push_back("     and mixing_chamber_stages = N (-s key=value, or in the printer profile).");
    lines.push_back(
        "  The model: N stirred tanks in series, V mm3 together. After v mm3 of the new filament");
    lines.push_back("  the nozzle lets out 1 - e^-t (1 + t + ... + t^(N-1)/(N-1)!) of it, t = v N / V.");
    lines.push_back("  Computed on it: the 50 % point lies near V (1 - 1/(3N)), and the 10-90 % width");
    lines.push_back("  narrows about as 1/sqrt(N):");
}

void addFactors(std::vector<std::string>& lines) {
    lines.push_back(
        "     N   10 %     50 %     90 %    90/10  1-1/(3N)  10-90 width  width x sqrt(N)  (units of V)");
    for (int n : candidateStages()) {
        const StepPoints p = stepPoints(ChamberSpec{1.0, n});
        lines.push_back(format("  %4d   %.3f    %.3f    %.3f   %5.2f   %.3f     %.3f        %.2f", n, p.v10,
                               p.v50, p.v90, p.v90 / p.v10, 1.0 - 1.0 / (3.0 * n), p.v90 - p.v10,
                               (p.v90 - p.v10) * std::sqrt(static_cast<double>(n))));
    }
}

void addTable(const CalibrationTower& t, std::vector<std::string>& lines) {
    const double band = t.switch2_mm - t.switch1_mm;
    lines.push_back(
        "Heights above a switch (mm) where the colour is 10 / 50 / 90 % of the way to the new filament:");
    lines.push_back(format("  %4s  %5s ", "N", "V mm3") + format("  %5s", "10 %") + " " +
                    format("  %5s", "50 %") + " " + format("  %5s", "90 %"));
    for (int n : candidateStages()) {
        for (double v : candidateVolumesMm3()) {
            const StepPoints p = stepPoints(ChamberSpec{v, n});
            lines.push_back(format("  %4d  %5.0f ", n, v) + heightCell(p.v10 / t.per_mm_mm3, band) + " " +
                            heightCell(p.v50 / t.per_mm_mm3, band) + " " +
                            heightCell(p.v90 / t.per_mm_mm3, band));
        }
    }
    lines.push_back(format(
        "  (>%.1f: beyond the %.1f mm band of one colour; a chamber that large needs --band.", band, band));
    lines.push_back("  The switch back reads as the first one when the colour had settled before it.)");
}

void addCurrent(const CalibrationTower& t, std::vector<std::string>& lines) {
    if (t.current.ideal()) {
        lines.push_back("The profile now: mixing_chamber_volume 0 (an ideal chamber, no delay assumed).");
        return;
    }
    const StepPoints p = stepPoints(t.current);
    lines.push_back(format("The profile now: mixing_chamber_volume %g mm3, mixing_chamber_stages %d;",
                           t.current.volume_mm3, t.current.stages));
    lines.push_back(format("  they predict 10 / 50 / 90 %% at %.2f / %.2f / %.2f mm above a switch.",
                           p.v10 / t.per_mm_mm3, p.v50 / t.per_mm_mm3, p.v90 / t.per_mm_mm3));
}

}  // namespace

double volumeToFraction(const ChamberSpec& spec, double fraction) {
    if (spec.ideal() || fraction <= 0)
        return 0;
    if (fraction >= 1)
        return INFINITY;  // approached, never reached
    double lo = 0, hi = spec.volume_mm3;
    while (outletShare(spec, hi) < fraction)
        hi *= 2;
    while (hi - lo > 1e-6) {
        const double mid = (lo + hi) / 2;
        (outletShare(spec, mid) < fraction ? lo : hi) = mid;
    }
    return (lo + hi) / 2;
}

StepPoints stepPoints(const ChamberSpec& spec) {
    return {volumeToFraction(spec, 0.1), volumeToFraction(spec, 0.5), volumeToFraction(spec, 0.9)};
}

std::vector<double> candidateVolumesMm3() {
    return {10, 20, 30, 40, 50, 60, 80, 100, 120};
}

std::vector<int> candidateStages() {
    return {1, 2, 3, 4, 6, 10};
}

std::vector<std::string> calibrationGuide(const CalibrationTower& tower) {
    std::vector<std::string> lines;
    addHeader(tower, lines);
    addHowTo(tower, lines);
    addFactors(lines);
    addTable(tower, lines);
    addCurrent(tower, lines);
    return lines;
}

}  // namespace mixengine
