#include "pipeline/FffProcessor.h"

#include <algorithm>
#include <cmath>

#include "common/Error.h"
#include "gcode/GCodeExport.h"
#include "gcode/PlanWriter.h"
#include "gcode/StartEndCode.h"
#include "planning/PrintPlanner.h"
#include "toolpaths/MeshToolpaths.h"

namespace mixengine {
namespace {

SlicingTolerance toleranceOf(const Settings& s) {
    const std::string text = s.has("slicing_tolerance") ? s.text("slicing_tolerance") : "middle";
    if (text == "inclusive")
        return SlicingTolerance::Inclusive;
    if (text == "exclusive")
        return SlicingTolerance::Exclusive;
    return SlicingTolerance::Middle;
}

ExportParams exportParams(const Scene& scene) {
    const Settings& global = scene.machine.global;
    const Settings& e0 = scene.machine.extruders.front();
    ExportParams p;
    p.filament_diameter_mm = e0.millimetres("material_diameter");
    p.volumetric = flavorFromSetting(global.text("machine_gcode_flavor")) == Flavor::MarlinVolumetric;
    p.relative_extrusion = global.boolean("relative_extrusion");
    p.retraction_amount_mm = e0.boolean("retraction_enable") ? e0.millimetres("retraction_amount") : 0.0;
    p.retraction_speed_mm_s = e0.velocityMmPerS("retraction_retract_speed");
    p.prime_speed_mm_s = e0.velocityMmPerS("retraction_prime_speed");
    p.retraction_hop_um = e0.boolean("retraction_hop_enabled") ? e0.lengthMicrons("retraction_hop") : 0;
    return p;
}

PrintPlan planGroup(const SceneGroup& group, const SlicedGroup& sliced, int threads) {
    std::vector<MeshToolpathsInput> inputs;
    for (std::size_t m = 0; m < group.meshes.size(); ++m) {
        MeshToolpathsInput input;
        input.settings = &group.meshes[m].settings;
        input.name = group.meshes[m].mesh.name;
        input.layers = generateMeshToolpaths(sliced.meshes[m], group.meshes[m].settings, threads);
        inputs.push_back(std::move(input));
    }
    return planPrint(sliced.heights, inputs, group.settings);
}

double perimeterUm(const Path& path) {
    double sum = 0;
    for (std::size_t i = 0; i < path.size(); ++i) {
        const Point2& a = path[i];
        const Point2& b = path[(i + 1) % path.size()];
        sum += std::hypot(static_cast<double>(b.X - a.X), static_cast<double>(b.Y - a.Y));
    }
    return sum;
}

/// As CuraEngine: loops shorter than minimum_polygon_circumference are dropped. The layer count
/// stays what the layer heights say, even when the top layers end up empty. (Outline
/// simplification by meshfix_maximum_resolution / _deviation is left to the toolpath work.)
void cleanOutlines(SlicedGroup& sliced, coord_um minimum_circumference_um) {
    for (auto& mesh : sliced.meshes) {
        for (SlicedLayer& layer : mesh) {
            std::erase_if(layer.outlines,
                          [&](const Path& p) { return perimeterUm(p) < double(minimum_circumference_um); });
        }
    }
}

}  // namespace

std::string GCodeOutput::joined() const {
    std::string text = prefix;
    for (const std::string& chunk : layer_chunks)
        text += chunk;
    return text + suffix;
}

SlicedGroup sliceGroup(const SceneGroup& group, int threads, Log& log) {
    SlicedGroup sliced;
    coord_um max_z = 0;
    for (const SceneMesh& m : group.meshes)
        max_z = std::max(max_z, m.mesh.bounds().max.z);
    const Settings& s = group.settings;
    sliced.heights =
        computeLayerHeights(max_z, s.lengthMicrons("layer_height_0"), s.lengthMicrons("layer_height"));
    SliceOptions options;
    options.tolerance = toleranceOf(s);
    options.threads = threads;
    for (const SceneMesh& m : group.meshes)
        sliced.meshes.push_back(sliceMesh(m.mesh, sliced.heights, options, log));
    cleanOutlines(sliced, s.lengthMicrons("minimum_polygon_circumference"));
    return sliced;
}

GCodeOutput runPipeline(const Scene& scene, int threads, Log& log) {
    const Settings& global = scene.machine.global;
    GCodeExport gcode(exportParams(scene));
    PlanWriterParams writer;
    writer.layer_change_speed_mm_s = global.velocityMmPerS("speed_z_hop");

    GCodeOutput output;
    output.summary.min = {INT64_MAX, INT64_MAX, INT64_MAX};
    output.summary.max = {INT64_MIN, INT64_MIN, INT64_MIN};
    int layer_offset = 0;
    for (const SceneGroup& group : scene.groups) {
        if (group.meshes.empty())
            continue;
        log.progress("slicing", 0.0);
        SlicedGroup sliced = sliceGroup(group, threads, log);
        log.progress("toolpaths", 0.3);
        PrintPlan plan = planGroup(group, sliced, threads);
        for (PlannedLayer& layer : plan.layers)
            layer.index += layer_offset;
        layer_offset += static_cast<int>(plan.layers.size());
        log.progress("gcode", 0.8);
        WrittenLayers written = writePlan(plan, writer, gcode);
        output.summary.min = {std::min(output.summary.min.x, written.min.x),
                              std::min(output.summary.min.y, written.min.y),
                              std::min(output.summary.min.z, written.min.z)};
        output.summary.max = {std::max(output.summary.max.x, written.max.x),
                              std::max(output.summary.max.y, written.max.y),
                              std::max(output.summary.max.z, written.max.z)};
        for (std::string& chunk : written.chunks)
            output.layer_chunks.push_back(std::move(chunk));
    }
    if (output.layer_chunks.empty())
        output.summary.min = output.summary.max = {};

    const bool relative = global.boolean("relative_extrusion");
    output.summary.flavor = flavorFromSetting(global.text("machine_gcode_flavor"));
    output.summary.print_time_s = gcode.elapsedSeconds();
    output.summary.filament_per_extruder = {gcode.filamentUsedMm()};
    output.summary.layer_height_mm = global.millimetres("layer_height");
    output.summary.engine_version = MIXENGINE_VERSION;
    output.prefix = makeHeader(output.summary) + startCode(global, scene.machine.extruders.front(), relative);
    if (!relative)
        output.prefix += "G92 E0\n";
    output.prefix += ";LAYER_COUNT:" + std::to_string(output.layer_chunks.size()) + "\n";
    output.suffix = endCode(global, relative) + ";End of Gcode\n";
    log.progress("done", 1.0);
    return output;
}

}  // namespace mixengine
