#include "gcode/StartEndCode.h"

#include "gcode/NumberFormat.h"

namespace mixengine {

namespace {

void appendLine(std::string& out, const std::string& line) {
    out += line;
    if (out.empty() || out.back() != '\n')
        out += '\n';
}

}  // namespace

namespace {

std::string flavorText(const Settings& global) {
    return global.has("machine_gcode_flavor") ? global.text("machine_gcode_flavor")
                                              : "RepRap (Marlin/Sprinter)";
}

double initialNozzleTemperature(const Settings& extruder0) {
    const double first = extruder0.temperatureCelsius("material_print_temperature_layer_0");
    return first != 0 ? first : extruder0.temperatureCelsius("material_print_temperature");
}

/// The temperature lines Cura prepends; RepRap firmware gets no M105 and no M140 before M190.
std::string prependedTemperatures(const Settings& global, const Settings& extruder0, bool reprap) {
    std::string out;
    const bool heated_bed = global.has("machine_heated_bed") && global.boolean("machine_heated_bed");
    const double bed = global.temperatureCelsius("material_bed_temperature_layer_0");
    if (heated_bed && bed != 0 && global.boolean("material_bed_temp_prepend")) {
        const bool wait = global.boolean("material_bed_temp_wait");
        if (!reprap || !wait)
            appendLine(out, "M140 S" + formatDecimal(bed, 1));
        if (wait) {
            if (!reprap)
                appendLine(out, "M105");
            appendLine(out, "M190 S" + formatDecimal(bed, 1));
        }
    }
    if (global.boolean("material_print_temp_prepend")) {
        const double nozzle = initialNozzleTemperature(extruder0);
        appendLine(out, "M104 S" + formatDecimal(nozzle, 1));
        if (global.boolean("material_print_temp_wait")) {
            if (!reprap)
                appendLine(out, "M105");
            appendLine(out, "M109 S" + formatDecimal(nozzle, 1));
        }
    }
    return out;
}

}  // namespace

std::string startCode(const Settings& global, const Settings& extruder0, bool relative_extrusion) {
    const std::string flavor = flavorText(global);
    const bool reprap = flavor == "RepRap (RepRap)";
    const bool griffin = flavor == "Griffin";
    std::string out;
    if (reprap || griffin)
        appendLine(out,
                   "T" + std::to_string(extruder0.has("extruder_nr") ? extruder0.integer("extruder_nr") : 0));
    if (!griffin && flavor != "UltiGCode")
        out += prependedTemperatures(global, extruder0, reprap);
    appendLine(out, "M82 ;absolute extrusion mode");
    appendLine(out, global.text("machine_start_gcode"));
    if (griffin)
        appendLine(out, "M109 S" + formatDecimal(initialNozzleTemperature(extruder0), 1));
    if (relative_extrusion)
        appendLine(out, "M83 ;relative extrusion mode");
    return out;
}

std::string endCode(const Settings& global, bool relative_extrusion) {
    std::string out;
    if (relative_extrusion)
        appendLine(out, "M82 ;absolute extrusion mode");
    appendLine(out, global.text("machine_end_gcode"));
    // As CuraEngine: the file ends in absolute mode, except on RepRap firmware (relative by default).
    const bool reprap =
        global.has("machine_gcode_flavor") && global.text("machine_gcode_flavor") == "RepRap (RepRap)";
    appendLine(out, reprap ? "M83 ;relative extrusion mode" : "M82 ;absolute extrusion mode");
    return out;
}

}  // namespace mixengine
