#pragma once
// Start and end G-code: the temperature lines Cura prepends (material_bed_temp_prepend,
// material_print_temp_prepend and their *_wait flags), the machine's start/end code as the
// settings hold it (tokens were expanded by the frontend, or by settings/FrontendValues for the
// command line), the extrusion mode lines, and what CuraEngine writes around them.
#include <string>
#include <vector>

#include "gcode/GCodeExport.h"
#include "settings/Settings.h"

namespace mixengine {

/// The start: temperatures, M82, machine_start_gcode, the heated build volume (M141), M83, as the
/// flavor's row says (gcode/Flavor.h: start_selects_tool, prepends_temperatures, m105_before_wait,
/// nozzle_wait_m116, build_volume_temperature, heats_nozzle_after_start).
std::string startCode(const Settings& global, const FlavorTraits& flavor, const Settings& extruder0,
                      bool relative_extrusion);

/// The temperature startCode() leaves the first nozzle at, and whether it waited for it (set = false:
/// the start code sets none).
struct StartTemperature {
    bool set = false;
    double celsius = 0;
    bool waited = false;
};
StartTemperature startNozzleTemperature(const Settings& global, const FlavorTraits& flavor,
                                        const Settings& extruder0);

/// An extruder's prime train (CuraEngine's writePrimeTrain), at its first use: with prime_blob_enable
/// a travel to extruder_prime_pos_x/_y (absolute, or from where the head is); on Griffin
/// (gcode.flavor().firmware_prime) `G280` (`G280 S1` without a blob, then Z written again, as the
/// firmware may move it); then the extruder's retraction (without z-hop). Nothing when the extruder is primed
/// already (machine_extruders_share_nozzle: the start code primes them all).
struct PrimeTrain {
    bool blob = false;  ///< prime_blob_enable
    Point2 position_um{0, 0};
    bool absolute = true;  ///< extruder_prime_pos_abs
    double travel_speed_mm_s = 150;
};
void writePrimeTrain(const PrimeTrain& prime, GCodeExport& gcode);

/// machine_end_gcode between the extrusion-mode lines CuraEngine writes (M83 last when the
/// flavor's ends_relative).
std::string endCode(const Settings& global, const FlavorTraits& flavor, bool relative_extrusion);

/// Everything after the last layer, as CuraEngine 4.13 writes it: a last retraction, the bed
/// (M140 S0) and a heated build volume (M141 S0, when gcode.flavor() has build_volume_temperature)
/// switched off, the fan off, endCode(), every nozzle switched off (M104 [T<n>] S0, none when
/// machine_nozzle_temp_enabled is false) and ";End of Gcode".
std::string finishPrint(GCodeExport& gcode, const Settings& global, const std::vector<Settings>& extruders,
                        bool relative_extrusion);

}  // namespace mixengine
