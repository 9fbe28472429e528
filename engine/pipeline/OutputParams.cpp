#include "pipeline/OutputParams.h"

#include <algorithm>
#include <numbers>

#include "mixing/MixingSettings.h"

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
    p.filament_diameter_mm = e0.millimetres("material_diameter");
    const Flavor flavor = flavorFromSetting(global.text("machine_gcode_flavor"));
    p.volumetric = flavor == Flavor::MarlinVolumetric || flavor == Flavor::UltiGCode;
    p.relative_extrusion = relativeExtrusion(global);  // mixing/MixingSettings.h: M83 when a dialect needs it
    p.retraction_amount_mm = e0.boolean("retraction_enable") ? e0.millimetres("retraction_amount") : 0.0;
    p.retraction_speed_mm_s = e0.velocityMmPerS("retraction_retract_speed");
    p.prime_speed_mm_s = e0.velocityMmPerS("retraction_prime_speed");
    p.retraction_hop_um = e0.boolean("retraction_hop_enabled") ? e0.lengthMicrons("retraction_hop") : 0;
    p.firmware_retract = e0.has("machine_firmware_retract") && e0.boolean("machine_firmware_retract");
    if (e0.has("retraction_extra_prime_amount"))
        p.extra_prime_mm3 = std::max(0.0, e0.real("retraction_extra_prime_amount"));
    p.kinematics = kinematicsOf(global);
    p.mixing = parseMixingOutput(global);
    p.motion_flavor = motionFlavor(global.text("machine_gcode_flavor"));
    return p;
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
        out.start_code = e.text("machine_extruder_start_code");
        out.end_code = e.text("machine_extruder_end_code");
        if (scene.machine.extruders.size() > 1) {
            out.print_temperature_c = e.temperatureCelsius("material_print_temperature");
            out.standby_temperature_c = e.temperatureCelsius("material_standby_temperature");
        }
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
        h.initial_temperature_c = e.temperatureCelsius("material_print_temperature_layer_0");
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
