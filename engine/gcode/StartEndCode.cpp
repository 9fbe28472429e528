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

std::string startCode(const Settings& global, const Settings& extruder0, bool relative_extrusion) {
    std::string out;
    const bool heated_bed = global.has("machine_heated_bed") && global.boolean("machine_heated_bed");
    const double bed = global.temperatureCelsius("material_bed_temperature_layer_0");
    if (heated_bed && bed != 0 && global.boolean("material_bed_temp_prepend")) {
        appendLine(out, "M140 S" + formatDecimal(bed, 1));
        if (global.boolean("material_bed_temp_wait")) {
            appendLine(out, "M105");
            appendLine(out, "M190 S" + formatDecimal(bed, 1));
        }
    }
    if (global.boolean("material_print_temp_prepend")) {
        double nozzle = extruder0.temperatureCelsius("material_print_temperature_layer_0");
        if (nozzle == 0)
            nozzle = extruder0.temperatureCelsius("material_print_temperature");
        appendLine(out, "M104 S" + formatDecimal(nozzle, 1));
        if (global.boolean("material_print_temp_wait")) {
            appendLine(out, "M105");
            appendLine(out, "M109 S" + formatDecimal(nozzle, 1));
        }
    }
    appendLine(out, "M82 ;absolute extrusion mode");
    appendLine(out, global.text("machine_start_gcode"));
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
