#include "gcode/StartEndCode.h"

#include "gcode/NumberFormat.h"

namespace mixengine {

namespace {

void appendLine(std::string& out, const std::string& line) {
    out += line;
    if (out.empty() || out.back() != '\n')
        out += '\n';
}

std::string temperature(const Settings& settings, const char* key) {
    return formatDecimal(settings.temperatureCelsius(key), 1);
}

}  // namespace

std::string startCode(const Settings& global, const Settings& extruder0, bool relative_extrusion) {
    std::string out;
    const bool heated_bed = global.has("machine_heated_bed") && global.boolean("machine_heated_bed");
    if (heated_bed && global.boolean("material_bed_temp_prepend")) {
        const std::string bed = temperature(global, "material_bed_temperature_layer_0");
        appendLine(out, "M140 S" + bed);
        appendLine(out, "M105");
        if (global.boolean("material_bed_temp_wait"))
            appendLine(out, "M190 S" + bed);
    }
    if (global.boolean("material_print_temp_prepend")) {
        const std::string nozzle = temperature(extruder0, "material_print_temperature_layer_0");
        appendLine(out, "M104 S" + nozzle);
        appendLine(out, "M105");
        if (global.boolean("material_print_temp_wait"))
            appendLine(out, "M109 S" + nozzle);
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
    if (relative_extrusion)
        appendLine(out, "M82 ;absolute extrusion mode");
    return out;
}

}  // namespace mixengine
