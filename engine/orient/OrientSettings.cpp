#include "orient/OrientSettings.h"

#include <cstdio>

#include "common/Error.h"
#include "orient/MeshRotation.h"

namespace mixengine::orient {
namespace {

std::string badValue(const std::string& what, const std::string& text, const std::string& allowed) {
    return what + ": unknown value '" + text + "' (" + allowed + ")";
}

}  // namespace

Method parseMethod(const std::string& text, const std::string& what) {
    if (text == "sphere")
        return Method::Sphere;
    if (text == "grid")
        return Method::Grid;
    throw InputError(badValue(what, text, "sphere or grid"));
}

Measure parseMeasure(const std::string& text, const std::string& what) {
    if (text == "own_part" || text == "own")
        return Measure::OwnPart;
    if (text == "all_material" || text == "all")
        return Measure::AllMaterial;
    throw InputError(badValue(what, text, "own_part or all_material"));
}

Objective parseObjective(const std::string& text, const std::string& what) {
    if (text == "flat_face")
        return Objective::FlatFace;
    if (text == "low_height")
        return Objective::LowHeight;
    if (text == "low_overhang")
        return Objective::LowOverhang;
    throw InputError(badValue(what, text, "flat_face, low_height or low_overhang"));
}

OrientOptions optionsFromSettings(const Settings& global) {
    OrientOptions o;
    o.method = parseMethod(global.text(key::dual_orientation_method), "dual_orientation_method");
    o.measure = parseMeasure(global.text(key::dual_orientation_measure), "dual_orientation_measure");
    o.objective = parseObjective(global.text(key::dual_orientation_objective), "dual_orientation_objective");
    o.resolution = static_cast<int>(global.integer(key::dual_orientation_resolution));
    o.verify = static_cast<int>(global.integer(key::dual_orientation_verify_count));
    o.grid_step_deg = global.angleDegrees(key::dual_orientation_grid_step);
    o.overhang_angle_deg = global.angleDegrees(key::support_angle);
    if (o.resolution < 8 || o.resolution > 1024)
        throw InputError("dual_orientation_resolution: " + std::to_string(o.resolution) +
                         " is not in 8..1024");
    if (!(o.grid_step_deg >= 1 && o.grid_step_deg <= 90))
        throw InputError("dual_orientation_grid_step: must be between 1 and 90 degrees");
    return o;
}

Vec3 nozzleOffsetMm(const std::vector<Settings>& extruders) {
    if (extruders.size() < 2)
        throw InputError("orient: the machine has " + std::to_string(extruders.size()) +
                         " extruder train(s); the nozzle offset needs two");
    return {extruders[1].millimetres(key::machine_nozzle_offset_x) -
                extruders[0].millimetres(key::machine_nozzle_offset_x),
            extruders[1].millimetres(key::machine_nozzle_offset_y) -
                extruders[0].millimetres(key::machine_nozzle_offset_y),
            0.0};
}

void orientForDualNozzle(const std::vector<std::pair<Mesh*, int>>& meshes_by_extruder, const Settings& global,
                         const std::vector<Settings>& extruders, Log& log) {
    if (!global.boolean(key::dual_orientation_optimize))
        return;
    std::vector<const Mesh*> part[2];
    std::vector<Mesh*> moved;
    for (const auto& [mesh, extruder] : meshes_by_extruder) {
        if (extruder == 0 || extruder == 1) {
            part[extruder].push_back(mesh);
            moved.push_back(mesh);
        }
    }
    if (part[0].empty() || part[1].empty()) {
        log.warning(
            "dual_orientation_optimize: nothing to optimise: the models use only one of extruders 0 and 1");
        return;
    }
    const Vec3 offset = nozzleOffsetMm(extruders);
    if (length(offset) <= 0) {
        log.warning(
            "dual_orientation_optimize: nothing to optimise: the nozzle offsets of extruders 0 and 1 are "
            "equal");
        return;
    }
    const Mesh a = concatenated(part[0], "extruder 0"), b = concatenated(part[1], "extruder 1");
    const OrientResult result = optimiseOrientation(a, b, offset, optionsFromSettings(global), log);
    rotateTogether(moved, result.rotation, result.centre_mm);
    char text[256];
    std::snprintf(
        text, sizeof text,
        "dual_orientation_optimize: latitude %.2f, longitude %.2f, spin %.2f deg; V %.1f -> %.1f mm3 (%s)",
        result.angles.latitude_deg, result.angles.longitude_deg, result.spin_deg, result.v_before_mm3,
        result.v_after_mm3, result.exact ? "exact" : "voxel");
    log.info(text);
}

}  // namespace mixengine::orient
