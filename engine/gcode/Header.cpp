#include "gcode/Header.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "gcode/format/NumberFormat.h"

namespace mixengine {

namespace {

/// Six significant digits, as CuraEngine prints filament amounts ("2.55346m", "123457mm3").
std::string significant(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", value);
    return buffer;
}

std::string filamentList(const PrintSummary& summary) {
    std::string text;
    const bool volumetric = flavorTraits(summary.flavor).volumetric_e;
    for (std::size_t i = 0; i < summary.filament_per_extruder.size(); ++i) {
        if (i)
            text += ", ";
        const double value = summary.filament_per_extruder[i];
        text += volumetric ? significant(value) + "mm3" : significant(value / 1000.0) + "m";
    }
    return text.empty() ? "0m" : text;
}

/// "<key>X:x", "<key>Y:y", "<key>Z:z" lines of a corner, in millimetres.
std::string cornerLines(const std::string& key, const Point3& corner_um) {
    return key + "X:" + formatCoordMm(micronsToMm(corner_um.x)) + "\n" + key +
           "Y:" + formatCoordMm(micronsToMm(corner_um.y)) + "\n" + key +
           "Z:" + formatCoordMm(micronsToMm(corner_um.z)) + "\n";
}

/// The six bounding-box lines, min corner first: (";MIN", ";MAX") gives ";MINX:" ... ";MAXZ:".
std::string boundsLines(const PrintSummary& summary, const std::string& min_key, const std::string& max_key) {
    return cornerLines(min_key, summary.min) + cornerLines(max_key, summary.max);
}

std::string seconds(double s) {
    return std::to_string(static_cast<long long>(s));
}

std::string griffinHeader(const PrintSummary& summary) {
    std::string h = ";START_OF_HEADER\n;HEADER_VERSION:0.1\n;FLAVOR:";
    h += flavorTraits(summary.flavor).header_name;
    h += "\n";
    h += ";GENERATOR.NAME:MixEngine\n;GENERATOR.VERSION:" + summary.engine_version + "\n";
    h += ";TARGET_MACHINE.NAME:" + summary.machine_name + "\n";
    for (std::size_t i = 0; i < summary.extruders.size(); ++i) {
        const ExtruderHeader& e = summary.extruders[i];
        if (!e.used)
            continue;
        const std::string train = ";EXTRUDER_TRAIN." + std::to_string(i) + ".";
        h += train + "INITIAL_TEMPERATURE:" + formatDecimal(e.initial_temperature_c, 1) + "\n";
        h += train + "MATERIAL.VOLUME_USED:" + std::to_string(std::llround(e.volume_used_mm3)) + "\n";
        if (!e.material_guid.empty())
            h += train + "MATERIAL.GUID:" + e.material_guid + "\n";
        h += train + "NOZZLE.DIAMETER:" + formatDecimal(e.nozzle_diameter_mm, 3) + "\n";
        h += train + "NOZZLE.NAME:" + e.nozzle_name + "\n";
    }
    h += ";BUILD_PLATE.TYPE:" + summary.build_plate_type + "\n";
    h += ";BUILD_PLATE.INITIAL_TEMPERATURE:" + formatDecimal(summary.build_plate_temperature_c, 1) + "\n";
    h += ";PRINT.TIME:" + seconds(summary.print_time_s) + "\n";
    h += ";PRINT.GROUPS:" + std::to_string(summary.print_groups) + "\n";
    h += boundsLines(summary, ";PRINT.SIZE.MIN.", ";PRINT.SIZE.MAX.");
    h += ";END_OF_HEADER\n";
    return h;
}

std::string ultiGCodeHeader(const PrintSummary& summary) {
    std::string h = ";FLAVOR:";
    h += flavorTraits(summary.flavor).header_name;
    h += "\n;TIME:" + seconds(summary.print_time_s) + "\n";
    for (std::size_t i = 0; i < std::max<std::size_t>(summary.extruders.size(), 2); ++i) {
        const double volume = i < summary.extruders.size() ? summary.extruders[i].volume_used_mm3 : 0.0;
        h += ";MATERIAL" + (i == 0 ? std::string() : std::to_string(i + 1)) + ":" +
             std::to_string(std::llround(volume)) + "\n";
    }
    const double nozzle = summary.extruders.empty() ? 0.4 : summary.extruders.front().nozzle_diameter_mm;
    h += ";NOZZLE_DIAMETER:" + formatDecimal(nozzle, 3) + "\n";
    return h + boundsLines(summary, ";MIN", ";MAX");
}

}  // namespace

std::string makeHeader(const PrintSummary& summary) {
    std::string generated = "\n;Generated with MixEngine " + summary.engine_version + "\n";
    for (const std::string& line : summary.extra_lines)
        generated += ";" + line + "\n";
    const FlavorTraits& flavor = flavorTraits(summary.flavor);
    if (flavor.header == HeaderStyle::Griffin)
        return griffinHeader(summary) + generated;
    if (flavor.header == HeaderStyle::UltiGCode)
        return ultiGCodeHeader(summary) + generated;
    std::string h = ";FLAVOR:";
    h += flavor.header_name;
    h += "\n;TIME:" + std::to_string(static_cast<long long>(summary.print_time_s)) + "\n";
    if (flavor.header == HeaderStyle::Long) {
        h += ";Filament used: " + filamentList(summary) + "\n";
        h += ";Layer height: " + formatDecimal(summary.layer_height_mm, 3) + "\n";
    }
    return h + boundsLines(summary, ";MIN", ";MAX") + generated;
}

}  // namespace mixengine
