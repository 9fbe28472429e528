#include "gcode/Flavor.h"

#include <array>

namespace mixengine {

namespace {

constexpr MotionForms kRepRapMotion{"M204 P", "M204 T", false, "M566 X", true, 60};
constexpr MotionForms kRepetierMotion{"M201 X", "M202 X", true, "M207 X", false, 1};

/// One row per flavor; what a row leaves out is Marlin's (the defaults of FlavorTraits).
constexpr std::array<FlavorTraits, 10> kFlavors{{
    {.flavor = Flavor::Marlin, .setting = "RepRap (Marlin/Sprinter)", .m105_before_wait = true},
    {.flavor = Flavor::MarlinVolumetric,
     .setting = "RepRap (Volumetric)",
     .header_name = "Marlin(Volumetric)",
     .volumetric_e = true},
    {.flavor = Flavor::RepRap,
     .setting = "RepRap (RepRap)",
     .header_name = "RepRap",
     .start_selects_tool = true,
     .ends_relative = true,
     .motion = kRepRapMotion},
    {.flavor = Flavor::UltiGCode,
     .setting = "UltiGCode",
     .header_name = "UltiGCode",
     .header = HeaderStyle::UltiGCode,
     .volumetric_e = true,
     .prepends_temperatures = false,
     .build_volume_temperature = false},
    {.flavor = Flavor::Griffin,
     .setting = "Griffin",
     .header_name = "Griffin",
     .header = HeaderStyle::Griffin,
     .start_selects_tool = true,
     .prepends_temperatures = false,
     .heats_nozzle_after_start = true,
     .build_volume_temperature = false,
     .firmware_prime = true},
    {.flavor = Flavor::Makerbot,
     .setting = "Makerbot",
     .header_name = "Makerbot",
     .header = HeaderStyle::Short,
     .nozzle_wait_m116 = true,
     .fan_on_off = true},
    {.flavor = Flavor::Bfb,
     .setting = "BFB",
     .header_name = "BFB",
     .header = HeaderStyle::Short,
     .rpm_extrusion = true,
     .auto_retraction = true,
     .crlf_line_ends = true,
     .resets_e_each_layer = false},
    {.flavor = Flavor::Mach3,
     .setting = "MACH3",
     .header_name = "Mach3",
     .header = HeaderStyle::Short,
     .axis = 'A',
     .axis_per_extruder = true},
    {.flavor = Flavor::Repetier,
     .setting = "Repetier",
     .header_name = "Repetier",
     .header = HeaderStyle::Short,
     .motion = kRepetierMotion},
    {.flavor = Flavor::Unknown, .setting = ""},
}};

}  // namespace

Flavor parseFlavor(std::string_view setting) {
    for (const FlavorTraits& row : kFlavors)
        if (!row.setting.empty() && row.setting == setting)
            return row.flavor;
    return Flavor::Unknown;
}

const FlavorTraits& flavorTraits(Flavor flavor) {
    for (const FlavorTraits& row : kFlavors)
        if (row.flavor == flavor)
            return row;
    return kFlavors.back();
}

const FlavorTraits& flavorOf(std::string_view setting) {
    return flavorTraits(parseFlavor(setting));
}

}  // namespace mixengine
