#include "pipeline/FffProcessor.h"

#include <algorithm>

#include "gcode/StartEndCode.h"
#include "mixing/MixingPass.h"
#include "mixing/MixingSettings.h"
#include "pipeline/OutputParams.h"
#include "planning/PrintPlanner.h"
#include "slicing/OutlineCleanup.h"
#include "toolpaths/GroupToolpaths.h"

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

PrintPlan planGroup(const Scene& scene, const SceneGroup& group, const SlicedGroup& sliced, int threads,
                    PlannerState& state, Log& log) {
    ToolpathInput input;
    input.global = &group.settings;
    input.extruders = &scene.machine.extruders;
    input.heights = sliced.heights;
    for (std::size_t m = 0; m < group.meshes.size(); ++m) {
        input.meshes.push_back({&group.meshes[m].settings, group.meshes[m].mesh.name, &sliced.meshes[m]});
    }
    const GroupToolpaths toolpaths = generateGroupToolpaths(input, threads);
    for (const std::string& warning : toolpaths.warnings)
        log.warning(warning);
    for (const std::string& note : toolpaths.notes)
        log.info(note);
    return planPrint(toolpaths, group.settings, scene.machine.extruders, state);
}

MixingGroup mixingInput(const SceneGroup& group) {
    MixingGroup input{&group.settings, {}};
    for (const SceneMesh& m : group.meshes) {
        const AABB3 box = m.mesh.bounds();
        input.meshes.push_back({&m.settings, box.min.z, box.max.z});
    }
    return input;
}

/// "a.stl", "a.stl, b.stl", or "a.stl, b.stl and 3 more meshes" for messages.
std::string meshNames(const Scene& scene) {
    std::vector<std::string> names;
    for (const SceneGroup& group : scene.groups)
        for (const SceneMesh& m : group.meshes)
            names.push_back(m.mesh.name);
    std::string text;
    for (std::size_t i = 0; i < names.size() && i < 2; ++i)
        text += (i ? ", " : "") + names[i];
    if (names.size() > 2)
        text += " and " + std::to_string(names.size() - 2) + " more meshes";
    return text.empty() ? "the scene" : text;
}

}  // namespace

std::string GCodeOutput::joined() const {
    std::string text = header + start;
    for (const std::string& chunk : layer_chunks)
        text += chunk;
    return text + suffix;
}

SlicedGroup sliceGroup(const SceneGroup& group, int threads, Log& log, bool simplify) {
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
    OutlineCleanupParams cleanup;
    cleanup.minimum_circumference_um = s.lengthMicrons("minimum_polygon_circumference");
    cleanup.maximum_resolution_um = simplify ? s.lengthMicrons("meshfix_maximum_resolution") : 0;
    cleanup.maximum_deviation_um = simplify ? s.lengthMicrons("meshfix_maximum_deviation") : 0;
    for (std::size_t m = 0; m < sliced.meshes.size(); ++m) {
        cleanOutlines(sliced.meshes[m], cleanup, threads);
        const Settings& own = group.meshes[m].settings;
        if (own.has("meshfix_union_all_remove_holes") && own.boolean("meshfix_union_all_remove_holes"))
            removeHoles(sliced.meshes[m], threads);
    }
    return sliced;
}

GCodeOutput runPipeline(const Scene& scene, int threads, Log& log, const PlanObserver& on_plan) {
    const Settings& global = scene.machine.global;
    const ExportParams export_params = exportParams(scene);
    GCodeExport gcode(export_params);
    const PlanWriterParams writer = writerParams(scene);
    PlannerState state;

    GCodeOutput output;
    output.summary.min = {INT64_MAX, INT64_MAX, INT64_MAX};
    output.summary.max = {INT64_MIN, INT64_MIN, INT64_MIN};
    int layer_offset = 0;
    for (const SceneGroup& group : scene.groups) {
        if (group.meshes.empty())
            continue;
        log.progress(ProgressStage::Slicing, 0.0);
        SlicedGroup sliced = sliceGroup(group, threads, log);
        log.progress(ProgressStage::Toolpaths, 0.3);
        PrintPlan plan = planGroup(scene, group, sliced, threads, state, log);
        assignMixes(plan, mixingInput(group), log);
        if (on_plan)
            on_plan(plan);
        for (PlannedLayer& layer : plan.layers)
            layer.index += layer_offset;
        layer_offset += static_cast<int>(plan.layers.size());
        log.progress(ProgressStage::GCode, 0.8);
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
    if (output.layer_chunks.empty()) {
        output.summary.min = output.summary.max = {};
        log.warning("nothing to print: no part of " + meshNames(scene) +
                    " lies at a slice height above the build plate (0 layers)");
    }

    const bool relative = relativeExtrusion(global);
    output.summary.flavor = flavorFromSetting(global.text("machine_gcode_flavor"));
    output.summary.print_time_s = gcode.elapsedSeconds();
    output.summary.time_by_feature_s = gcode.secondsByFeature();
    output.summary.filament_per_extruder = gcode.filamentPerExtruder();
    output.summary.filament_per_extruder.resize(scene.machine.extruders.size(), 0.0);
    describeExtruders(scene, export_params.volumetric, output.summary);
    output.summary.layer_height_mm = global.millimetres("layer_height");
    output.summary.engine_version = MIXENGINE_VERSION;
    output.header = makeHeader(output.summary);
    output.start = startCode(global, scene.machine.extruders.front(), relative);
    if (!relative)
        output.start += "G92 E0\n";
    output.start += ";LAYER_COUNT:" + std::to_string(output.layer_chunks.size()) + "\n";
    output.suffix = finishPrint(gcode, global, scene.machine.extruders, relative);
    log.progress(ProgressStage::Done, 1.0);
    return output;
}

}  // namespace mixengine
