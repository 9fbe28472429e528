#pragma once
// What Cura's frontend adds to the settings before it sends them to its engine
// (CuraEngineBackend/StartSliceJob.py), done here so the command line gives what Cura gives:
//   - material_bed_temp_prepend / material_print_temp_prepend: True when the start G-code (its
//     comments removed) references none of the bed / nozzle temperature settings as {key} or
//     {key, extruder_nr} — unless the user set them;
//   - machine_start_gcode / machine_end_gcode (global, with the initial extruder's values) and
//     machine_extruder_start_code / machine_extruder_end_code (each extruder, its own values) with
//     their {key} and {key, N} tokens expanded; unknown tokens ({print_time}, ...) stay verbatim;
//   - the renamed copies print_bed_temperature, print_temperature, travel_speed, and
//     initial_extruder_nr. Cura's time, date and day are available to start/end code tokens but
//     are not kept in the settings, so that resolving twice gives the same values.
#include <string>

#include "settings/Resolver.h"

namespace mixengine {

/// Expands {key} and {key, N} tokens: `key` read from extruder N's values (or `scope`'s).
std::string expandGcodeTokens(const std::string& code, const Settings& scope, const ResolvedMachine& machine);

/// Applies the frontend's additions to `machine` (global and extruders). `user` tells which
/// prepend flags the user set explicitly.
void applyFrontendValues(ResolvedMachine& machine, const UserSettings& user);

/// Seed 001's setting names, accepted wherever user values arrive (-s, -g, -e, per model, or
/// Cura's socket) and turned into MixEngine's keys here, in one place, before resolution:
///   colorMode, colorMixing → mixing_mode (0 / 1 / 2 or single / dual / gradient)
///   colorA → mixing_gradient_start, colorB → mixing_gradient_end (percent of the model height, so
///   mixing_gradient_unit becomes percent unless it is given too).
/// An alias whose canonical key is also given with another value is an InputError naming both.
SettingValues withCanonicalKeys(const SettingValues& values);
UserSettings withCanonicalKeys(const UserSettings& user);

}  // namespace mixengine
