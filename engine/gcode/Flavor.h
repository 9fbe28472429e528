#pragma once
// machine_gcode_flavor in one place: the firmware flavors Cura offers, parsed from the setting's
// text here only (parseFlavor), and one row per flavor (FlavorTraits, the table in Flavor.cpp) of
// everything the G-code stage writes differently for it. The rest of the engine asks the row for a
// fact (volumetric_e, fan_on_off, motion, ...) and never names a flavor. Adding a flavor is adding its
// enum value and its row, and its line in the test of the table.
//
// The table keeps what the engine wrote before it existed, which is CuraEngine 4.13's output for
// every option of Cura's machine_gcode_flavor. Any other text is Unknown: Marlin's header and
// commands, but none of Marlin's temperature waits (M105, M140 before M190); CuraEngine treats any
// other text as Marlin in full.
#include <string_view>

namespace mixengine {

/// Cura's machine_gcode_flavor options, and Unknown for any other text.
enum class Flavor {
    Marlin,
    MarlinVolumetric,
    RepRap,
    UltiGCode,
    Griffin,
    Makerbot,
    Bfb,
    Mach3,
    Repetier,
    Unknown
};

/// How the file header is laid out (gcode/Header.h).
enum class HeaderStyle {
    Griffin,    ///< the ;START_OF_HEADER … ;END_OF_HEADER block
    UltiGCode,  ///< ;FLAVOR:, ;TIME:, ;MATERIAL: per train, ;NOZZLE_DIAMETER:, bounds
    Long,       ///< ;FLAVOR:, ;TIME:, ;Filament used:, ;Layer height:, bounds
    Short,      ///< ;FLAVOR:, ;TIME:, bounds
};

/// The acceleration and jerk commands (gcode/MotionCommands.h): "<print_acceleration><a>[ Y<a>]",
/// "<jerk><j·jerk_scale>[ Y<j·jerk_scale>]".
struct MotionForms {
    std::string_view print_acceleration;   ///< e.g. "M204 S", "M204 P", "M201 X"
    std::string_view travel_acceleration;  ///< empty: one acceleration for print and travel moves
    bool acceleration_y = false;           ///< the value again as " Y<a>"
    std::string_view jerk;                 ///< e.g. "M205 X"
    bool jerk_y = true;                    ///< the value again as " Y<j>"
    double jerk_scale = 1;                 ///< jerk_print is mm/s: 60 writes mm/min
};

/// Everything the G-code stage does differently by flavor; the defaults are what most flavors do
/// (Marlin's row differs only in m105_before_wait).
struct FlavorTraits {
    Flavor flavor = Flavor::Marlin;
    std::string_view setting;                 ///< the machine_gcode_flavor text (Unknown: empty)
    std::string_view header_name = "Marlin";  ///< ";FLAVOR:<header_name>"
    HeaderStyle header = HeaderStyle::Long;   ///< gcode/Header.h
    bool volumetric_e = false;                ///< E words in mm³ of material, not mm of filament
    char axis = 'E';                          ///< the extrusion axis of extruder 0
    bool axis_per_extruder = false;           ///< extruder n's axis is axis + n (A, B, ...)
    /// BFB's extruder motor (gcode/Bfb.h): M108/M101 and M103 instead of E words, Z on every move,
    /// the firmware retracts when the motor stops
    bool rpm_extrusion = false;
    bool auto_retraction = false;           ///< M227 after the start code (gcode/Bfb.h)
    bool crlf_line_ends = false;            ///< every line the engine writes ends in "\r\n"
    bool resets_e_each_layer = true;        ///< G92 E0 at each layer start in absolute mode
    bool start_selects_tool = false;        ///< T<n> of the first extruder opens the start code
    bool prepends_temperatures = true;      ///< material_*_temp_prepend lines before the start code
    bool m105_before_wait = false;          ///< M105 before M109/M190, M140 before M190
    bool nozzle_wait_m116 = false;          ///< the start code waits with M104 + M116, not M109
    bool heats_nozzle_after_start = false;  ///< M109 of the first nozzle after the start code
    bool build_volume_temperature = true;   ///< M141 for machine_heated_build_volume
    bool ends_relative = false;             ///< M83 is the last line (the firmware's default mode)
    bool firmware_prime = false;            ///< G280 primes an extruder at its first use
    bool fan_on_off = false;                ///< M126 T0 / M127 T0 instead of M106 S / M107
    MotionForms motion{"M204 S", "", false, "M205 X", true, 1};
};

/// The flavor named by a machine_gcode_flavor text; Unknown for any other text (no error, as before).
Flavor parseFlavor(std::string_view setting);

/// The row of `flavor`.
const FlavorTraits& flavorTraits(Flavor flavor);

/// The row of a machine_gcode_flavor text: flavorTraits(parseFlavor(setting)).
const FlavorTraits& flavorOf(std::string_view setting);

}  // namespace mixengine
