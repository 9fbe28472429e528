#include "gcode/Bfb.h"

#include <cmath>

#include "gcode/format/NumberFormat.h"

namespace mixengine {

double BfbMotor::extrude(double filament_mm_per_mm, double speed_mm_s, int extruder, std::string& lines) {
    // CuraEngine computes these in float; the written values follow its rounding.
    float feedrate = static_cast<float>(speed_mm_s * 60.0);
    float rpm = static_cast<float>(filament_mm_per_mm * speed_mm_s * 60.0);
    constexpr float kMmPerRevolution = 4.0F;
    rpm /= kMmPerRevolution;
    if (rpm <= 0)
        return feedrate;
    if (stopped_) {
        if (rpm != rpm_set_) {
            lines += "M108 S" + formatDecimal(static_cast<double>(rpm), 1) + "\n";
            rpm_set_ = rpm;
        }
        lines += "M" + std::to_string((extruder + 1) * 100 + 1) + "\n";
        stopped_ = false;
    }
    const float settable = std::round(rpm * 100.0F) / 100.0F;  // the RPM the firmware can take
    if (settable > 0)
        feedrate *= rpm / settable;
    return feedrate;
}

std::string BfbMotor::stop() {
    if (stopped_)
        return "";
    stopped_ = true;
    return "M103\n";
}

std::string BfbMotor::prime() {
    if (!stopped_)
        return "";
    stopped_ = false;
    return "G11\n";
}

std::string bfbMove(const Point2& xy_um, coord_um z_um, double feedrate_mm_min) {
    return "G1 X" + formatCoordMm(micronsToMm(xy_um.X)) + " Y" + formatCoordMm(micronsToMm(xy_um.Y)) + " Z" +
           formatCoordMm(micronsToMm(z_um)) + " F" + formatDecimal(feedrate_mm_min, 1);
}

std::string bfbAutoRetraction(coord_um retraction_amount_um, bool retraction_enable) {
    const std::string n = std::to_string(retraction_amount_um * 2560 / 1000);
    return ";enable auto-retraction\nM227 S" + n + " P" + n + "\n" + (retraction_enable ? "G92 E0\n" : "");
}

namespace {

void appendCrLf(std::string& out, const std::string& text, std::size_t from, std::size_t to) {
    for (std::size_t i = from; i < to; ++i) {
        if (text[i] == '\n')
            out += '\r';
        out += text[i];
    }
}

}  // namespace

std::string withBfbLineEnds(const std::string& text, const std::vector<std::string>& verbatim) {
    std::vector<bool> keep(text.size(), false);
    for (const std::string& block : verbatim) {
        const std::size_t line_end = block.find('\n');
        if (line_end == std::string::npos || line_end + 1 >= block.size())
            continue;  // a single line: nothing inside to keep
        for (std::size_t at = text.find(block); at != std::string::npos;
             at = text.find(block, at + block.size()))
            for (std::size_t i = at; i < at + block.size(); ++i)
                keep[i] = true;
    }
    std::string out;
    out.reserve(text.size() + text.size() / 16);
    std::size_t start = 0;
    for (std::size_t i = 0; i <= text.size(); ++i) {
        if (i == text.size() || keep[i]) {
            appendCrLf(out, text, start, i);
            if (i < text.size())
                out += text[i];
            start = i + 1;
        }
    }
    return out;
}

}  // namespace mixengine
