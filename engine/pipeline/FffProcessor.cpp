#include "pipeline/FffProcessor.h"

#include <algorithm>

#include "gcode/StartEndCode.h"
#include "mixing/MixingPass.h"
#include "mixing/MixingSettings.h"
#include "pipeline/OutputParams.h"
#include "planning/PrintPlanner.h"
#include "slicing/OutlineCleanup.h"
#include "toolpaths/GroupToolpaths.h"
#include "toolpaths/RaftLayout.h"

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
        const AABB3 box = group.meshes[m].mesh.bounds();
        const Point2 middle{(box.min.x + box.max.x) / 2, (box.min.y + box.max.y) / 2};
        input.meshes.push_back(
            {&group.meshes[m].settings, group.meshes[m].mesh.name, &sliced.meshes[m], middle});
    }
    const GroupToolpaths toolpaths = generateGroupToolpaths(input, threads);
    for (const std::string& warning : toolpaths.warnings)
        log.warning(warning);
    for (const std::string& note : toolpaths.notes)
        log.info(note);
    return planPrint(toolpaths, group.settings, scene.machine.extruders, state);
}

/// The mixing stage's view of the group: each mesh's height span as printed, i.e. lifted by the
/// raft (toolpaths/RaftLayout.h) like the layers whose z the schedules are read at.
MixingGroup mixingInput(const Scene& scene, const SceneGroup& group) {
    MixingGroup input{&group.settings, {}};
    const coord_um lift = raftLayout(group.settings, &scene.machine.extruders).modelLiftUm(1);
    for (const SceneMesh& m : group.meshes) {
        const AABB3 box = m.mesh.bounds();
        input.meshes.push_back({&m.settings, m.mesh.name, box.min.z + lift, box.max.z + lift, &m.mesh, lift});
    }
    return input;
}

/// Numbers the plan's layers on from `next_index` (the first group keeps CuraEngine's numbers,
/// negative raft layers included); returns the index after the last layer.
int renumber(PrintPlan& plan, int next_index, bool first_group) {
    if (plan.layers.empty())
        return next_index;
    const int offset = first_group ? 0 : next_index - plan.layers.front().index;
    for (PlannedLayer& layer : plan.layers)
        layer.index += offset;
    return plan.layers.back().index + 1;
}

/// The layers of the model (not the raft's): CuraEngine's ;LAYER_COUNT:.
int modelLayers(const PrintPlan& plan) {
    return static_cast<int>(std::count_if(plan.layers.begin(), plan.layers.end(),
                                          [](const PlannedLayer& layer) { return layer.index >= 0; }));
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

/// As CuraEngine's start: with machine_extruders_share_nozzle every filament is primed and pulled back
/// machine_extruders_shared_nozzle_initial_retraction; on Griffin the first extruder is primed
/// (gcode/StartEndCode.h writePrimeTrain). Returns the text for the end of the start code.
std::string primeFirstExtruder(const Scene& scene, const PlanWriterParams& writer, GCodeExport& gcode) {
    if (scene.machine.global.boolean("machine_extruders_share_nozzle")) {
        for (std::size_t e = 0; e < scene.machine.extruders.size(); ++e)
            gcode.assumePrimed(
                static_cast<int>(e),
                scene.machine.extruders[e].millimetres("machine_extruders_shared_nozzle_initial_retraction"));
    }
    if (!writer.griffin || writer.extruders.empty())
        return "";
    writePrimeTrain(writer.extruders.front().prime, true, gcode);
    return gcode.takeText();
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
    const StartTemperature start = startNozzleTemperature(global, scene.machine.extruders.front());
    if (start.set)
        gcode.assumeNozzleTemperature(0, start.celsius, start.waited);
    const PlanWriterParams writer = writerParams(scene);
    const std::string prime = primeFirstExtruder(scene, writer, gcode);
    PlannerState state;
    // As CuraEngine, the first layer is planned from layer_start_x/_y of the first extruder (later
    // layers go on from where the one before ended).
    const Settings& first = scene.machine.extruders.front();
    state.head = {first.lengthMicrons("layer_start_x"), first.lengthMicrons("layer_start_y")};

    GCodeOutput output;
    output.summary.min = {INT64_MAX, INT64_MAX, INT64_MAX};
    output.summary.max = {INT64_MIN, INT64_MIN, INT64_MIN};
    int next_index = 0;
    int model_layers = 0;
    for (const SceneGroup& group : scene.groups) {
        if (group.meshes.empty())
            continue;
        log.progress(ProgressStage::Slicing, 0.0);
        SlicedGroup sliced = sliceGroup(group, threads, log);
        log.progress(ProgressStage::Toolpaths, 0.3);
        PrintPlan plan = planGroup(scene, group, sliced, threads, state, log);
        assignMixes(plan, mixingInput(scene, group), log);
        model_layers += modelLayers(plan);
        next_index = renumber(plan, next_index, output.layer_chunks.empty());
        if (on_plan)
            on_plan(plan);
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
    output.start += prime;
    output.start += ";LAYER_COUNT:" + std::to_string(model_layers) + "\n";  // as CuraEngine: not the raft's
    output.suffix = finishPrint(gcode, global, scene.machine.extruders, relative);
    log.progress(ProgressStage::Done, 1.0);
    return output;
}

}  // namespace mixengine
