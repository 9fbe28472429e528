#include "pipeline/OutputParams.h"

#include <algorithm>
#include <numbers>

#include "mixing/setup/MixingSettings.h"

namespace mixengine {

Kinematics kinematicsOf(const Settings& g) {
    Kinematics k;
    k.acceleration_mm_s2 = g.boolean("acceleration_enabled") ? g.accelerationMmPerS2("acceleration_print")
                                                             : g.accelerationMmPerS2("machine_acceleration");
    k.jerk_xy_mm_s =
        g.boolean("jerk_enabled") ? g.velocityMmPerS("jerk_print") : g.velocityMmPerS("machine_max_jerk_xy");
    k.jerk_z_mm_s = g.velocityMmPerS("machine_max_jerk_z");
    k.jerk_e_mm_s = g.velocityMmPerS("machine_max_jerk_e");
    k.minimum_feedrate_mm_s = g.velocityMmPerS("machine_minimum_feedrate");
    const char* axes[] = {"x", "y", "z", "e"};
    for (int i = 0; i < 4; ++i) {
        k.max_acceleration_mm_s2[i] =
            g.accelerationMmPerS2(std::string("machine_max_acceleration_") + axes[i]);
        k.max_feedrate_mm_s[i] = g.velocityMmPerS(std::string("machine_max_feedrate_") + axes[i]);
    }
    return k;
}

ExportParams exportParams(const Scene& scene) {
    const Settings& global = scene.machine.global;
    const Settings& e0 = scene.machine.extruders.front();
    ExportParams p;
    p.flavor = flavorOf(global.text("machine_gcode_flavor"));  // the one read of the flavor
    p.filament_diameter_mm = e0.millimetres("material_diameter");
    p.relative_extrusion =
        relativeExtrusion(global);  // mixing/setup/MixingSettings.h: M83 when a dialect needs it
    p.retraction_amount_mm = e0.boolean("retraction_enable") ? e0.millimetres("retraction_amount") : 0.0;
    p.retraction_speed_mm_s = e0.velocityMmPerS("retraction_retract_speed");
    p.prime_speed_mm_s = e0.velocityMmPerS("retraction_prime_speed");
    p.retraction_hop_um = e0.boolean("retraction_hop_enabled") ? e0.lengthMicrons("retraction_hop") : 0;
    p.retraction_extra_prime_mm3 = e0.real("retraction_extra_prime_amount");
    p.z_hop_speed_mm_s = e0.velocityMmPerS("speed_z_hop");
    p.firmware_retract = e0.flag("machine_firmware_retract");
    p.temperatures = temperatureCommandParams(scene);
    p.fan_number = static_cast<int>(e0.integer("machine_extruder_cooling_fan_number"));
    p.kinematics = kinematicsOf(global);
    p.mixing = parseMixingOutput(global);

    if (global.has("flow_rate_max_extrusion_offset")) {
        p.flow_offset_max = global.real("flow_rate_max_extrusion_offset");
        p.flow_offset_factor = global.ratio("flow_rate_extrusion_offset_factor");
    }
    return p;
}

TemperatureCommandParams temperatureCommandParams(const Scene& scene) {
    const Settings& global = scene.machine.global;
    TemperatureCommandParams t;
    t.share_heater = global.boolean("machine_extruders_share_heater");
    t.always_write_active_tool = global.boolean("machine_always_write_active_tool");
    for (const Settings& e : scene.machine.extruders)
        t.controlled.push_back(e.boolean("machine_nozzle_temp_enabled"));
    return t;
}

RetractionConfig travelRetraction(const Settings& e) {
    return {e.boolean("retraction_enable") ? e.millimetres("retraction_amount") : 0.0,
            e.velocityMmPerS("retraction_retract_speed"), e.velocityMmPerS("retraction_prime_speed"),
            e.real("retraction_extra_prime_amount")};
}

PrimeTrain primeTrain(const Settings& e) {
    PrimeTrain prime;
    prime.blob = e.boolean("prime_blob_enable");
    prime.position_um = {e.lengthMicrons("extruder_prime_pos_x"), e.lengthMicrons("extruder_prime_pos_y")};
    prime.absolute = e.boolean("extruder_prime_pos_abs");
    prime.travel_speed_mm_s = e.velocityMmPerS("speed_travel");
    return prime;
}

/// The wipe script of train `e` (clean_between_layers).
WipeScriptConfig wipeScript(const Settings& e) {
    WipeScriptConfig w;
    w.retraction_enable = e.boolean("wipe_retraction_enable");
    w.retraction = {
        e.millimetres("wipe_retraction_amount"), e.velocityMmPerS("wipe_retraction_retract_speed"),
        e.velocityMmPerS("wipe_retraction_prime_speed"), e.real("wipe_retraction_extra_prime_amount")};
    w.pause_s = e.durationSeconds("wipe_pause");
    w.hop_enable = e.boolean("wipe_hop_enable");
    w.hop_um = e.lengthMicrons("wipe_hop_amount");
    w.hop_speed_mm_s = e.velocityMmPerS("wipe_hop_speed");
    w.brush_x_um = e.lengthMicrons("wipe_brush_pos_x");
    w.repeat_count = static_cast<int>(e.integer("wipe_repeat_count"));
    w.move_distance_um = e.lengthMicrons("wipe_move_distance");
    w.move_speed_mm_s = e.velocityMmPerS("speed_travel");
    return w;
}

/// What switching away from / to train `e` does besides the tool change itself.
void switchParams(const Settings& e, ExtruderOutput& out) {
    out.retraction_enabled = e.boolean("retraction_enable");
    out.switch_retraction = {e.millimetres("switch_extruder_retraction_amount"),
                             e.velocityMmPerS("switch_extruder_retraction_speed"),
                             e.velocityMmPerS("switch_extruder_prime_speed"), 0.0};
    if (e.boolean("retraction_hop_after_extruder_switch"))
        out.switch_hop_um = e.lengthMicrons("retraction_hop_after_extruder_switch_height");
    out.switch_extra_prime_mm3 = e.real("switch_extruder_extra_prime_amount");
    out.prime = primeTrain(e);
}

PlanWriterParams writerParams(const Scene& scene) {
    const Settings& global = scene.machine.global;
    PlanWriterParams writer;
    writer.layer_change_speed_mm_s = global.velocityMmPerS("speed_z_hop");
    const bool offset_coords = !global.has("machine_use_extruder_offset_to_offset_coords") ||
                               global.boolean("machine_use_extruder_offset_to_offset_coords");
    for (std::size_t i = 0; i < scene.machine.extruders.size(); ++i) {
        const Settings& e = scene.machine.extruders[i];
        ExtruderOutput out;
        out.change.extruder = static_cast<int>(i);
        out.change.filament_diameter_mm = e.millimetres("material_diameter");
        if (offset_coords) {
            out.change.nozzle_offset_um = {e.lengthMicrons("machine_nozzle_offset_x"),
                                           e.lengthMicrons("machine_nozzle_offset_y")};
        }
        out.change.retraction = travelRetraction(e);
        out.change.retraction_hop_um =
            e.boolean("retraction_hop_enabled") ? e.lengthMicrons("retraction_hop") : 0;
        out.change.fan_number = static_cast<int>(e.integer("machine_extruder_cooling_fan_number"));
        out.start_code = e.text("machine_extruder_start_code");
        out.end_code = e.text("machine_extruder_end_code");
        switchParams(e, out);
        if (e.flag("clean_between_layers"))
            out.wipe = wipeScript(e);
        writer.extruders.push_back(std::move(out));
    }
    return writer;
}

void describeExtruders(const Scene& scene, bool volumetric, PrintSummary& summary) {
    const Settings& global = scene.machine.global;
    summary.machine_name = global.has("machine_name") ? global.text("machine_name") : "Unknown";
    summary.build_plate_type =
        global.has("machine_buildplate_type") ? global.text("machine_buildplate_type") : "glass";
    summary.build_plate_temperature_c = global.temperatureCelsius("material_bed_temperature_layer_0");
    summary.print_groups = static_cast<int>(scene.groups.size());
    for (std::size_t i = 0; i < scene.machine.extruders.size(); ++i) {
        const Settings& e = scene.machine.extruders[i];
        ExtruderHeader h;
        // As CuraEngine: the first extruder starts at its first-layer temperature, the others at standby.
        h.initial_temperature_c = i == 0 ? e.temperatureCelsius("material_print_temperature_layer_0")
                                         : e.temperatureCelsius("material_standby_temperature");
        h.nozzle_diameter_mm = e.millimetres("machine_nozzle_size");
        if (e.has("machine_nozzle_id"))
            h.nozzle_name = e.text("machine_nozzle_id");
        if (e.has("material_guid"))
            h.material_guid = e.text("material_guid");
        const double filament = summary.filament_per_extruder[i];
        const double radius = e.millimetres("material_diameter") / 2.0;
        h.volume_used_mm3 = volumetric ? filament : filament * std::numbers::pi * radius * radius;
        h.used = filament > 0;
        summary.extruders.push_back(std::move(h));
    }
}

}  // namespace mixengine
