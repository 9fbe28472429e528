#pragma once
// The G-code stage's parameters, built here from the resolved settings (settings/SettingKeys.h): the export
// parameters (filament, retraction, extrusion mode, mixing dialect, kinematics for the time estimate), the
// per-extruder tool-change data, and the header's description of each extruder train.
#include "gcode/GCodeExport.h"
#include "gcode/Header.h"
#include "gcode/PlanWriter.h"
#include "settings/Resolver.h"

namespace mixengine {

/// machine_acceleration / acceleration_print, jerk, per-axis limits (Cura's keys).
Kinematics kinematicsOf(const Settings& global);

/// The writer's parameters; `flavor` is the row of machine_gcode_flavor (gcode/Flavor.h), the one
/// place the setting is read: the rest of the G-code stage takes the flavor from here.
ExportParams exportParams(const ResolvedMachine& machine);

/// How nozzle temperature commands are written (shared heater, active tool, nozzle control).
TemperatureCommandParams temperatureCommandParams(const ResolvedMachine& machine);

PlanWriterParams writerParams(const ResolvedMachine& machine);

/// An extruder's prime train (prime_blob_enable, extruder_prime_pos_*, speed_travel).
PrimeTrain primeTrain(const Settings& extruder);

/// Fills summary.machine_name, build plate and summary.extruders (Griffin / UltiGCode headers);
/// summary.filament_per_extruder must already hold one value per extruder train.
void describeExtruders(const ResolvedMachine& machine, bool volumetric, PrintSummary& summary);

}  // namespace mixengine
