#include "gcode/OutputParams.h"

#include <algorithm>
#include <numbers>

#include "mixing/setup/MixingSettings.h"

namespace mixengine {

Kinematics kinematicsOf(const Settings& g) {
    Kinematics k;
    k.acceleration_mm_s2 = g.boolean(key::acceleration_enabled)
                               ? g.accelerationMmPerS2(key::acceleration_print)
                               : g.accelerationMmPerS2(key::machine_acceleration);
    k.jerk_xy_mm_s = g.boolean(key::jerk_enabled) ? g.velocityMmPerS(key::jerk_print)
                                                  : g.velocityMmPerS(key::machine_max_jerk_xy);
    k.jerk_z_mm_s = g.velocityMmPerS(key::machine_max_jerk_z);
    k.jerk_e_mm_s = g.velocityMmPerS(key::machine_max_jerk_e);
    k.minimum_feedrate_mm_s = g.velocityMmPerS(key::machine_minimum_feedrate);
    k.max_acceleration_mm_s2 = {g.accelerationMmPerS2(key::machine_max_acceleration_x),
                                g.accelerationMmPerS2(key::machine_max_acceleration_y),
                                g.accelerationMmPerS2(key::machine_max_acceleration_z),
                                g.accelerationMmPerS2(key::machine_max_acceleration_e)};
    k.max_feedrate_mm_s = {
        g.velocityMmPerS(key::machine_max_feedrate_x), g.velocityMmPerS(key::machine_max_feedrate_y),
        g.velocityMmPerS(key::machine_max_feedrate_z), g.velocityMmPerS(key::machine_max_feedrate_e)};
    return k;
}

ExportParams exportParams(const ResolvedMachine& machine) {
    const Settings& global = machine.global;
    const Settings& e0 = machine.extruders.front();
    ExportParams p;
    p.flavor = flavorOf(global.text(key::machine_gcode_flavor));  // the one read of the flavor
    p.filament_diameter_mm = e0.millimetres(key::material_diameter);
    p.relative_extrusion =
        relativeExtrusion(global);  // mixing/setup/MixingSettings.h: M83 when a dialect needs it
    p.retraction_amount_mm =
        e0.boolean(key::retraction_enable) ? e0.millimetres(key::retraction_amount) : 0.0;
    p.retraction_speed_mm_s = e0.velocityMmPerS(key::retraction_retract_speed);
    p.prime_speed_mm_s = e0.velocityMmPerS(key::retraction_prime_speed);
    p.retraction_hop_um = e0.boolean(key::retraction_hop_enabled) ? e0.lengthMicrons(key::retraction_hop) : 0;
    p.retraction_extra_prime_mm3 = e0.real(key::retraction_extra_prime_amount);
    p.z_hop_speed_mm_s = e0.velocityMmPerS(key::speed_z_hop);
    p.firmware_retract = e0.boolean(key::machine_firmware_retract);
    p.temperatures = temperatureCommandParams(machine);
    p.fan_number = static_cast<int>(e0.integer(key::machine_extruder_cooling_fan_number));
    p.kinematics = kinematicsOf(global);
    p.mixing = parseMixingOutput(global);

    p.flow_offset_max = global.millimetres(key::flow_rate_max_extrusion_offset);
    p.flow_offset_factor = global.ratio(key::flow_rate_extrusion_offset_factor);
    return p;
}

TemperatureCommandParams temperatureCommandParams(const ResolvedMachine& machine) {
    const Settings& global = machine.global;
    TemperatureCommandParams t;
    t.share_heater = global.boolean(key::machine_extruders_share_heater);
    t.always_write_active_tool = global.boolean(key::machine_always_write_active_tool);
    for (const Settings& e : machine.extruders)
        t.controlled.push_back(e.boolean(key::machine_nozzle_temp_enabled));
    return t;
}

RetractionConfig travelRetraction(const Settings& e) {
    return {e.boolean(key::retraction_enable) ? e.millimetres(key::retraction_amount) : 0.0,
            e.velocityMmPerS(key::retraction_retract_speed), e.velocityMmPerS(key::retraction_prime_speed),
            e.real(key::retraction_extra_prime_amount)};
}

PrimeTrain primeTrain(const Settings& e) {
    PrimeTrain prime;
    prime.blob = e.boolean(key::prime_blob_enable);
    prime.position_um = {e.lengthMicrons(key::extruder_prime_pos_x),
                         e.lengthMicrons(key::extruder_prime_pos_y)};
    prime.absolute = e.boolean(key::extruder_prime_pos_abs);
    prime.travel_speed_mm_s = e.velocityMmPerS(key::speed_travel);
    return prime;
}

/// The wipe script of train `e` (clean_between_layers).
WipeScriptConfig wipeScript(const Settings& e) {
    WipeScriptConfig w;
    w.retraction_enable = e.boolean(key::wipe_retraction_enable);
    w.retraction = {
        e.millimetres(key::wipe_retraction_amount), e.velocityMmPerS(key::wipe_retraction_retract_speed),
        e.velocityMmPerS(key::wipe_retraction_prime_speed), e.real(key::wipe_retraction_extra_prime_amount)};
    w.pause_s = e.durationSeconds(key::wipe_pause);
    w.hop_enable = e.boolean(key::wipe_hop_enable);
    w.hop_um = e.lengthMicrons(key::wipe_hop_amount);
    w.hop_speed_mm_s = e.velocityMmPerS(key::wipe_hop_speed);
    w.brush_x_um = e.lengthMicrons(key::wipe_brush_pos_x);
    w.repeat_count = static_cast<int>(e.integer(key::wipe_repeat_count));
    w.move_distance_um = e.lengthMicrons(key::wipe_move_distance);
    w.move_speed_mm_s = e.velocityMmPerS(key::speed_travel);
    return w;
}

/// What switching away from / to train `e` does besides the tool change itself.
void switchParams(const Settings& e, ExtruderOutput& out) {
    out.retraction_enabled = e.boolean(key::retraction_enable);
    out.switch_retraction = {e.millimetres(key::switch_extruder_retraction_amount),
                             e.velocityMmPerS(key::switch_extruder_retraction_speed),
                             e.velocityMmPerS(key::switch_extruder_prime_speed), 0.0};
    if (e.boolean(key::retraction_hop_after_extruder_switch))
        out.switch_hop_um = e.lengthMicrons(key::retraction_hop_after_extruder_switch_height);
    out.switch_extra_prime_mm3 = e.real(key::switch_extruder_extra_prime_amount);
    out.prime = primeTrain(e);
}

PlanWriterParams writerParams(const ResolvedMachine& machine) {
    const Settings& global = machine.global;
    PlanWriterParams writer;
    writer.layer_change_speed_mm_s = global.velocityMmPerS(key::speed_z_hop);
    const bool offset_coords = global.boolean(key::machine_use_extruder_offset_to_offset_coords);
    for (std::size_t i = 0; i < machine.extruders.size(); ++i) {
        const Settings& e = machine.extruders[i];
        ExtruderOutput out;
        out.change.extruder = static_cast<int>(i);
        out.change.filament_diameter_mm = e.millimetres(key::material_diameter);
        if (offset_coords) {
            out.change.nozzle_offset_um = {e.lengthMicrons(key::machine_nozzle_offset_x),
                                           e.lengthMicrons(key::machine_nozzle_offset_y)};
        }
        out.change.retraction = travelRetraction(e);
        out.change.retraction_hop_um =
            e.boolean(key::retraction_hop_enabled) ? e.lengthMicrons(key::retraction_hop) : 0;
        out.change.fan_number = static_cast<int>(e.integer(key::machine_extruder_cooling_fan_number));
        out.start_code = e.text(key::machine_extruder_start_code);
        out.end_code = e.text(key::machine_extruder_end_code);
        switchParams(e, out);
        if (e.boolean(key::clean_between_layers))
            out.wipe = wipeScript(e);
        writer.extruders.push_back(std::move(out));
    }
    return writer;
}

void describeExtruders(const ResolvedMachine& machine, bool volumetric, PrintSummary& summary) {
    const Settings& global = machine.global;
    summary.machine_name = global.text(key::machine_name);
    summary.build_plate_type = global.text(key::machine_buildplate_type);
    summary.build_plate_temperature_c = global.temperatureCelsius(key::material_bed_temperature_layer_0);
    for (std::size_t i = 0; i < machine.extruders.size(); ++i) {
        const Settings& e = machine.extruders[i];
        ExtruderHeader h;
        // As CuraEngine: the first extruder starts at its first-layer temperature, the others at standby.
        h.initial_temperature_c = i == 0 ? e.temperatureCelsius(key::material_print_temperature_layer_0)
                                         : e.temperatureCelsius(key::material_standby_temperature);
        h.nozzle_diameter_mm = e.millimetres(key::machine_nozzle_size);
        h.nozzle_name = e.text(key::machine_nozzle_id);
        h.material_guid = e.text(key::material_guid);
        const double filament = summary.filament_per_extruder[i];
        const double radius = e.millimetres(key::material_diameter) / 2.0;
        h.volume_used_mm3 = volumetric ? filament : filament * std::numbers::pi * radius * radius;
        h.used = filament > 0;
        summary.extruders.push_back(std::move(h));
    }
}

}  // namespace mixengine
