#include "gcode/StartEndCode.h"

#include "gcode/format/NumberFormat.h"

namespace mixengine {

namespace {

void appendLine(std::string& out, const std::string& line) {
    out += line;
    if (out.empty() || out.back() != '\n')
        out += '\n';
}

/// The user's G-code block and a line end, as CuraEngine writes it (a block ending in a line end
/// is followed by an empty line).
void appendCode(std::string& out, const std::string& code) {
    out += code;
    out += '\n';
}

}  // namespace

namespace {

double initialNozzleTemperature(const Settings& extruder0) {
    const double first = extruder0.temperatureCelsius(key::material_print_temperature_layer_0);
    return first != 0 ? first : extruder0.temperatureCelsius(key::material_print_temperature);
}

/// The temperature lines Cura prepends, as CuraEngine writes them per flavor: only Marlin sets the
/// target with M140 and asks M105 before waiting; Makerbot waits for the nozzle with M104 + M116.
std::string prependedTemperatures(const Settings& global, const Settings& extruder0,
                                  const FlavorTraits& flavor) {
    const bool marlin = flavor.m105_before_wait;
    std::string out;
    const bool heated_bed = global.boolean(key::machine_heated_bed);
    const double bed = global.temperatureCelsius(key::material_bed_temperature_layer_0);
    if (heated_bed && bed != 0 && global.boolean(key::material_bed_temp_prepend)) {
        const bool wait = global.boolean(key::material_bed_temp_wait);
        if (marlin || !wait)
            appendLine(out, "M140 S" + formatDecimal(bed, 1));
        if (wait) {
            if (marlin)
                appendLine(out, "M105");
            appendLine(out, "M190 S" + formatDecimal(bed, 1));
        }
    }
    const bool nozzle_control = extruder0.boolean(key::machine_nozzle_temp_enabled);
    if (global.boolean(key::material_print_temp_prepend) && nozzle_control) {
        const double nozzle = initialNozzleTemperature(extruder0);
        appendLine(out, "M104 S" + formatDecimal(nozzle, 1));
        if (global.boolean(key::material_print_temp_wait)) {
            if (marlin)
                appendLine(out, "M105");
            appendLine(out, flavor.nozzle_wait_m116 ? "M104 S" + formatDecimal(nozzle, 1) + "\nM116"
                                                    : "M109 S" + formatDecimal(nozzle, 1));
        }
    }
    return out;
}

bool heatedBuildVolume(const Settings& global) {
    return global.boolean(key::machine_heated_build_volume);
}

/// What CuraEngine switches off before the end code: the bed and the build volume.
std::string heatersOff(const Settings& global, const FlavorTraits& flavor) {
    std::string out;
    if (global.boolean(key::machine_heated_bed))
        appendLine(out, "M140 S0");
    if (heatedBuildVolume(global) && global.temperatureCelsius(key::build_volume_temperature) != 0 &&
        flavor.build_volume_temperature)
        appendLine(out, "M141 S0");
    return out;
}

/// M104 S0 for every nozzle after the end code (T<n> for all but the active one).
std::string nozzlesOff(const std::vector<Settings>& extruders, int active) {
    std::string out;
    for (std::size_t e = 0; e < extruders.size(); ++e) {
        if (!extruders[e].boolean(key::machine_nozzle_temp_enabled))
            continue;
        const bool current = static_cast<int>(e) == active;
        appendLine(out, current ? "M104 S0" : "M104 T" + std::to_string(e) + " S0");
    }
    return out;
}

}  // namespace

StartTemperature startNozzleTemperature(const Settings& global, const FlavorTraits& flavor,
                                        const Settings& extruder0) {
    const bool nozzle_control = extruder0.boolean(key::machine_nozzle_temp_enabled);
    if (flavor.heats_nozzle_after_start)
        return {true, initialNozzleTemperature(extruder0), true};
    if (!flavor.prepends_temperatures || !nozzle_control || !global.boolean(key::material_print_temp_prepend))
        return {};
    return {true, initialNozzleTemperature(extruder0), global.boolean(key::material_print_temp_wait)};
}

std::string startCode(const Settings& global, const FlavorTraits& flavor, const Settings& extruder0,
                      bool relative_extrusion) {
    std::string out;
    if (flavor.start_selects_tool)
        appendLine(out, "T" + std::to_string(extruder0.extruderIndex(key::extruder_nr)));
    if (flavor.prepends_temperatures)
        out += prependedTemperatures(global, extruder0, flavor);
    appendLine(out, "M82 ;absolute extrusion mode");
    appendCode(out, global.text(key::machine_start_gcode));
    if (heatedBuildVolume(global) && flavor.build_volume_temperature)
        appendLine(out,
                   "M141 S" + formatDecimal(global.temperatureCelsius(key::build_volume_temperature), 1));
    if (flavor.heats_nozzle_after_start)
        appendLine(out, "M109 S" + formatDecimal(initialNozzleTemperature(extruder0), 1));
    if (relative_extrusion)
        appendLine(out, "M83 ;relative extrusion mode");
    return out;
}

std::string finishPrint(GCodeExport& gcode, const Settings& global, const std::vector<Settings>& extruders,
                        bool relative_extrusion) {
    gcode.retract();
    std::string out = gcode.takeText() + heatersOff(global, gcode.flavor());
    if (global.boolean(key::acceleration_enabled)) {
        gcode.setMotion(global.accelerationMmPerS2(key::machine_acceleration), 0, false);
        gcode.setMotion(global.accelerationMmPerS2(key::machine_acceleration), 0, true);
    }
    if (global.boolean(key::jerk_enabled))
        gcode.setMotion(0, global.velocityMmPerS(key::machine_max_jerk_xy), false);
    out += gcode.takeText();
    if (relative_extrusion) {  // absolute mode before the fan and the end code, as CuraEngine
        appendLine(out, "M82 ;absolute extrusion mode");
        relative_extrusion = false;
    }
    gcode.setFan(0);
    out += gcode.takeText();
    return out + endCode(global, gcode.flavor(), relative_extrusion) +
           nozzlesOff(extruders, gcode.extruder()) + ";End of Gcode\n";
}

namespace {

/// The prime itself (see writePrimeTrain).
void primeOnce(const PrimeTrain& prime, GCodeExport& gcode) {
    if (prime.blob) {
        const Point2 here = gcode.position();
        const Point2 to = prime.absolute ? prime.position_um
                                         : Point2{here.X + prime.position_um.X, here.Y + prime.position_um.Y};
        gcode.travel(to, prime.travel_speed_mm_s);
    }
    if (gcode.flavor().firmware_prime) {
        gcode.line(prime.blob ? "G280" : "G280 S1");
        if (!prime.blob)
            gcode.line("G0 Z" + formatCoordMm(micronsToMm(gcode.z())));
    }
}

}  // namespace

void writePrimeTrain(const PrimeTrain& prime, GCodeExport& gcode) {
    if (gcode.markPrimed())
        primeOnce(prime, gcode);
    gcode.retractTo(gcode.retraction());
}

std::string endCode(const Settings& global, const FlavorTraits& flavor, bool relative_extrusion) {
    std::string out;
    if (relative_extrusion)
        appendLine(out, "M82 ;absolute extrusion mode");
    appendCode(out, global.text(key::machine_end_gcode));
    // As CuraEngine: the file ends in absolute mode, except on RepRap firmware (relative by default).
    appendLine(out, flavor.ends_relative ? "M83 ;relative extrusion mode" : "M82 ;absolute extrusion mode");
    return out;
}

}  // namespace mixengine
