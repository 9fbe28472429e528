#include "gcode/Header.h"

#include <cmath>
#include <cstdio>

#include "gcode/NumberFormat.h"

namespace mixengine {

Flavor flavorFromSetting(const std::string& text) {
    if (text == "RepRap (Marlin/Sprinter)")
        return Flavor::Marlin;
    if (text == "RepRap (Volumetric)")
        return Flavor::MarlinVolumetric;
    if (text == "RepRap (RepRap)")
        return Flavor::RepRap;
    if (text == "Griffin")
        return Flavor::Griffin;
    if (text == "UltiGCode")
        return Flavor::UltiGCode;
    return Flavor::Other;
}

std::string flavorName(Flavor flavor) {
    switch (flavor) {
        case Flavor::Marlin:
            return "Marlin";
        case Flavor::MarlinVolumetric:
            return "Marlin(Volumetric)";
        case Flavor::RepRap:
            return "RepRap";
        case Flavor::Griffin:
            return "Griffin";
        case Flavor::UltiGCode:
            return "UltiGCode";
        case Flavor::Other:
            break;
    }
    return "Marlin";
}

namespace {

/// Six significant digits, as CuraEngine prints filament amounts ("2.55346m", "123457mm3").
std::string significant(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", value);
    return buffer;
}

std::string filamentList(const PrintSummary& summary) {
    std::string text;
    const bool volumetric = summary.flavor == Flavor::MarlinVolumetric;
    for (std::size_t i = 0; i < summary.filament_per_extruder.size(); ++i) {
        if (i)
            text += ", ";
        const double value = summary.filament_per_extruder[i];
        text += volumetric ? significant(value) + "mm3" : significant(value / 1000.0) + "m";
    }
    return text.empty() ? "0m" : text;
}

}  // namespace

std::string makeHeader(const PrintSummary& summary) {
    std::string h;
    h += ";FLAVOR:" + flavorName(summary.flavor) + "\n";
    h += ";TIME:" + std::to_string(static_cast<long long>(summary.print_time_s)) + "\n";
    h += ";Filament used: " + filamentList(summary) + "\n";
    h += ";Layer height: " + formatDecimal(summary.layer_height_mm, 3) + "\n";
    h += ";MINX:" + formatCoordMm(micronsToMm(summary.min.x)) + "\n";
    h += ";MINY:" + formatCoordMm(micronsToMm(summary.min.y)) + "\n";
    h += ";MINZ:" + formatCoordMm(micronsToMm(summary.min.z)) + "\n";
    h += ";MAXX:" + formatCoordMm(micronsToMm(summary.max.x)) + "\n";
    h += ";MAXY:" + formatCoordMm(micronsToMm(summary.max.y)) + "\n";
    h += ";MAXZ:" + formatCoordMm(micronsToMm(summary.max.z)) + "\n";
    h += "\n;Generated with MixEngine " + summary.engine_version + "\n";
    return h;
}

}  // namespace mixengine
