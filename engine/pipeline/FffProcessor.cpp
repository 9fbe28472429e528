#include "pipeline/FffProcessor.h"

#include <algorithm>
#include <optional>

#include "common/Error.h"
#include "common/ParallelFor.h"
#include "gcode/Bfb.h"
#include "gcode/OutputParams.h"
#include "gcode/StartEndCode.h"
#include "mixing/MixingPass.h"
#include "mixing/setup/MixingSettings.h"
#include "pipeline/StreamedWriter.h"
#include "planning/PrintPlanner.h"
#include "slicing/MultiVolumes.h"

#include "slicing/AdaptiveLayers.h"
#include "slicing/OutlineCleanup.h"
#include "slicing/SlicingParams.h"
#include "toolpaths/GroupToolpaths.h"
#include "toolpaths/adhesion/RaftLayout.h"
#include "toolpaths/surface/ConicalOverhang.h"
#include "toolpaths/surface/Mold.h"

namespace mixengine {
namespace {

/// adaptive_layer_height_enabled: the group's layers from the slopes of its printed meshes
/// (slicing/AdaptiveLayers.h).
std::vector<LayerZ> adaptiveHeights(const SceneGroup& group, SlicingTolerance tolerance) {
    std::vector<FaceSlope> faces;
    for (const SceneMesh& m : group.meshes) {
        if (!volumeRoleOf(m.settings, m.mesh).printed())
            continue;
        std::vector<FaceSlope> own = faceSlopes(m.mesh);
        faces.insert(faces.end(), own.begin(), own.end());
    }
    return adaptiveLayerHeights(faces, adaptiveLayerParams(group.settings, tolerance));
}

/// As CuraEngine 4.13 after slicing: molds (toolpaths/surface/Mold.h), then each mesh's conical overhang
/// (toolpaths/surface/ConicalOverhang.h).
void reshapeOutlines(const SceneGroup& group, SlicedGroup& sliced) {
    std::vector<MoldMesh> molds;
    for (std::size_t m = 0; m < sliced.meshes.size(); ++m)
        molds.push_back({&sliced.meshes[m], &group.meshes[m].settings});
    applyMolds(molds, group.settings.lengthMicrons(key::layer_height));
    for (std::size_t m = 0; m < sliced.meshes.size(); ++m) {
        if (conicalOverhangWanted(group.meshes[m].settings))
            applyConicalOverhang(sliced.meshes[m], conicalOverhangParams(group.meshes[m].settings));
    }
}

/// Plans `group` into `plan` (empty at the call), handing each layer to `on_final` once it is final
/// (planning/PrintPlanner.h).
/// Before planning, `on_counted` hears how many model layers (CuraEngine's ;LAYER_COUNT:) the plan
/// will have: one per toolpaths height (the raft's layers are numbered below 0).
void planGroup(const Scene& scene, const SceneGroup& group, const SlicedGroup& sliced, int threads,
               PlannerState& state, Log& log, PrintPlan& plan, const FinalLayer& on_final,
               const std::function<void(int)>& on_counted) {
    ToolpathInput input;
    input.global = &group.settings;
    input.extruders = &scene.machine.extruders;
    input.heights = sliced.heights;
    input.on_progress = [&log](double share_done) { log.progress(ProgressStage::Toolpaths, share_done); };
    for (std::size_t m = 0; m < group.meshes.size(); ++m) {
        const AABB3 box = group.meshes[m].mesh.bounds();
        const Box2 flat{box.min.x, box.min.y, box.max.x, box.max.y};
        input.meshes.push_back(
            {&group.meshes[m].settings, group.meshes[m].mesh.name, &sliced.meshes[m], flat, sliced.roles[m]});
    }
    const GroupToolpaths toolpaths = generateGroupToolpaths(input, threads);
    for (const std::string& warning : toolpaths.warnings)
        log.warning(warning);
    for (const std::string& note : toolpaths.notes)
        log.info(note);
    on_counted(static_cast<int>(toolpaths.heights.size()));
    planPrint(plan, toolpaths, group.settings, scene.machine.extruders, state, threads, on_final);
}

/// Whether the group mixes colours (mixing/MixingPass.h assigns the mixes to the finished plan).
/// Bad mixing settings count as mixing: assignMixes() then reports them where it always does.
bool mixesColours(const Settings& group) {
    try {
        return parseMixingOutput(group).enabled();
    } catch (const InputError&) {
        return true;
    }
}

void extendBounds(PrintSummary& summary, const WrittenLayers& written) {
    summary.min = {std::min(summary.min.x, written.min.x), std::min(summary.min.y, written.min.y),
                   std::min(summary.min.z, written.min.z)};
    summary.max = {std::max(summary.max.x, written.max.x), std::max(summary.max.y, written.max.y),
                   std::max(summary.max.z, written.max.z)};
}

/// The mixing stage's view of the group: each mesh's height span as printed, i.e. lifted by the
/// raft (toolpaths/adhesion/RaftLayout.h) like the layers whose z the schedules are read at.
MixingGroup mixingInput(const Scene& scene, const SceneGroup& group) {
    MixingGroup input;
    input.settings = &group.settings;
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
    if (scene.machine.global.boolean(key::machine_extruders_share_nozzle)) {
        for (std::size_t e = 0; e < scene.machine.extruders.size(); ++e)
            gcode.assumePrimed(static_cast<int>(e),
                               scene.machine.extruders[e].millimetres(
                                   key::machine_extruders_shared_nozzle_initial_retraction));
    }
    if (!gcode.flavor().firmware_prime || writer.extruders.empty())
        return "";
    writePrimeTrain(writer.extruders.front().prime, gcode);
    return gcode.takeText();
}

/// Whether any mesh prints layers of its own (CuraEngine's print_layer_count counts neither infill
/// meshes, cutting meshes nor support blockers; support meshes count).
bool anyLayerMesh(const std::vector<VolumeRole>& roles) {
    return std::any_of(roles.begin(), roles.end(), [](const VolumeRole& r) {
        return !r.infill_mesh && !r.cutting_mesh && !r.anti_overhang_mesh;
    });
}

/// BFB: the user's G-code blocks, which keep their own line ends (gcode/Bfb.h).
std::vector<std::string> bfbVerbatim(const Scene& scene) {
    std::vector<std::string> verbatim = {scene.machine.global.text(key::machine_start_gcode),
                                         scene.machine.global.text(key::machine_end_gcode)};
    for (const Settings& e : scene.machine.extruders)
        for (const Key<SettingUnit::Text> key :
             {key::machine_extruder_start_code, key::machine_extruder_end_code})
            verbatim.push_back(e.text(key));
    return verbatim;
}

/// BFB: every line the engine wrote ends in \r\n; the user's G-code blocks keep their own line ends.
void useBfbLineEnds(const std::vector<std::string>& verbatim, GCodeOutput& output) {
    output.header = withBfbLineEnds(output.header, {});
    output.start = withBfbLineEnds(output.start, verbatim);
    for (std::string& chunk : output.layer_chunks)
        chunk = withBfbLineEnds(chunk, verbatim);
    output.suffix = withBfbLineEnds(output.suffix, verbatim);
}

/// The index of the last mesh group that has meshes (its layer count completes ;LAYER_COUNT:).
std::size_t lastGroupWithMeshes(const Scene& scene) {
    std::size_t last = 0;
    for (std::size_t g = 0; g < scene.groups.size(); ++g)
        if (!scene.groups[g].meshes.empty())
            last = g;
    return last;
}

/// The start code: the machine's start G-code, the extrusion reset, BFB's automatic retraction, the
/// first extruder's prime, then ;LAYER_COUNT: (the model's layers, not the raft's, as CuraEngine).
std::string startText(const Scene& scene, const ExportParams& export_params, const std::string& prime,
                      int model_layers) {
    const Settings& global = scene.machine.global;
    const Settings& first = scene.machine.extruders.front();
    const bool relative = relativeExtrusion(global);
    const FlavorTraits& flavor = export_params.flavor;
    std::string start = startCode(global, flavor, first, relative);
    if (!relative)
        start += std::string("G92 ") + flavor.axis + "0\n";
    if (flavor.auto_retraction)
        start += bfbAutoRetraction(first.lengthMicrons(key::retraction_amount),
                                   first.boolean(key::retraction_enable));
    start += prime;
    start += ";LAYER_COUNT:" + std::to_string(model_layers) + "\n";
    return start;
}

/// A finished plan's layers, written in order to `output`.
WrittenLayers writeLayers(const PrintPlan& plan, const PlanWriterParams& params, GCodeExport& gcode,
                          LayerOutput& output) {
    WrittenLayers written;
    const PlanTables tables{plan.mesh_names, plan.mixes, plan.outlet_colors};
    for (const PlannedLayer& layer : plan.layers) {
        writeLayer(layer, layer.index, tables, params, gcode, written);
        output.take(written.chunks, layer, layer.index);
    }
    return written;
}

/// The summary, the header and the end code once every layer is written.
void finishOutput(const Scene& scene, const ExportParams& export_params, GCodeExport& gcode,
                  GCodeOutput& output) {
    const Settings& global = scene.machine.global;
    output.summary.flavor = export_params.flavor.flavor;
    output.summary.print_time_s = gcode.elapsedSeconds();
    output.summary.time_by_feature_s = gcode.secondsByFeature();
    output.summary.filament_per_extruder = gcode.filamentPerExtruder();
    output.summary.filament_per_extruder.resize(scene.machine.extruders.size(), 0.0);
    output.summary.print_groups = static_cast<int>(scene.groups.size());
    describeExtruders(scene.machine, export_params.flavor.volumetric_e, output.summary);
    output.summary.layer_height_mm = global.millimetres(key::layer_height);
    output.summary.engine_version = MIXENGINE_VERSION;
    output.header = makeHeader(output.summary);
    output.suffix = finishPrint(gcode, global, scene.machine.extruders, relativeExtrusion(global));
    if (export_params.flavor.crlf_line_ends)
        useBfbLineEnds(bfbVerbatim(scene), output);
}

}  // namespace

std::vector<std::string_view> GCodeOutput::pieces() const {
    std::vector<std::string_view> out{header, start};
    out.insert(out.end(), layer_chunks.begin(), layer_chunks.end());
    out.push_back(suffix);
    return out;
}

std::string GCodeOutput::joined() const {
    std::size_t size = header.size() + start.size() + suffix.size();
    for (const std::string& chunk : layer_chunks)
        size += chunk.size();
    std::string text;
    text.reserve(size);
    text += header;
    text += start;
    for (const std::string& chunk : layer_chunks)
        text += chunk;
    text += suffix;
    return text;
}

SlicedGroup sliceGroup(const SceneGroup& group, int threads, Log& log, bool simplify) {
    SlicedGroup sliced;
    coord_um max_z = 0;
    for (const SceneMesh& m : group.meshes)
        max_z = std::max(max_z, m.mesh.bounds().max.z);
    const Settings& s = group.settings;
    SliceOptions options;
    options.tolerance = slicingToleranceOf(s);
    sliced.heights = s.boolean(key::adaptive_layer_height_enabled)
                         ? adaptiveHeights(group, options.tolerance)
                         : computeLayerHeights(max_z, s.lengthMicrons(key::layer_height_0),
                                               s.lengthMicrons(key::layer_height));
    options.threads = threads;
    setOutlineCleanup(options, s, simplify);  // prints follow CuraEngine; `layers` shows the exact cuts
    for (const SceneMesh& m : group.meshes) {
        SliceOptions own = options;
        own.union_all = m.settings.boolean(key::meshfix_union_all);
        own.keep_open_polygons = m.settings.boolean(key::meshfix_keep_open_polygons);
        own.max_gap_um = stitchDistanceUm(m.settings);
        sliced.meshes.push_back(sliceMesh(m.mesh, sliced.heights, own, log));
    }
    for (std::size_t m = 0; m < sliced.meshes.size(); ++m) {  // outlines cleaned while slicing (options)
        const Settings& own = group.meshes[m].settings;
        if (own.boolean(key::meshfix_union_all_remove_holes))
            removeHoles(sliced.meshes[m], threads);
        sliced.roles.push_back(volumeRoleOf(own, group.meshes[m].mesh));
    }
    combineVolumes(sliced.meshes, sliced.roles, volumeParams(s), threads);
    if (!anyLayerMesh(sliced.roles)) {  // only modifiers: nothing prints, as CuraEngine (0 layers)
        sliced.heights.clear();
        for (std::vector<SlicedLayer>& layers : sliced.meshes)
            layers.clear();
    }
    reshapeOutlines(group, sliced);
    return sliced;
}

GCodeOutput runPipeline(const Scene& scene, int threads, Log& log, const PlanObserver& on_plan,
                        const LayerStream& stream) {
    const Settings& global = scene.machine.global;
    const ExportParams export_params = exportParams(scene.machine);
    GCodeExport gcode(export_params);
    const StartTemperature start =
        startNozzleTemperature(global, export_params.flavor, scene.machine.extruders.front());
    if (start.set)
        gcode.assumeNozzleTemperature(0, start.celsius, start.waited);
    const PlanWriterParams writer = writerParams(scene.machine);
    const std::string prime = primeFirstExtruder(scene, writer, gcode);
    PlannerState state;
    // As CuraEngine, the first layer is planned from layer_start_x/_y of the first extruder (later
    // layers go on from where the one before ended).
    const Settings& first = scene.machine.extruders.front();
    state.head = {first.lengthMicrons(key::layer_start_x), first.lengthMicrons(key::layer_start_y)};

    GCodeOutput output;
    MixingReport mixing;                   // every group's, added up
    std::optional<Chamber> chamber_state;  // what the mixing chamber holds after the groups printed so far
    output.summary.min = {INT64_MAX, INT64_MAX, INT64_MAX};
    output.summary.max = {INT64_MIN, INT64_MIN, INT64_MIN};
    const bool crlf = export_params.flavor.crlf_line_ends;
    const std::vector<std::string> verbatim = crlf ? bfbVerbatim(scene) : std::vector<std::string>{};
    LayerOutput layers(stream, crlf ? &verbatim : nullptr, output.layer_chunks);
    const std::size_t last_group = lastGroupWithMeshes(scene);
    int next_index = 0;
    int model_layers = 0;
    std::optional<int> announced;  // the ;LAYER_COUNT: handed to the stream
    for (std::size_t g = 0; g < scene.groups.size(); ++g) {
        const SceneGroup& group = scene.groups[g];
        if (group.meshes.empty())
            continue;
        log.progress(ProgressStage::Slicing, 0.0);
        SlicedGroup sliced = sliceGroup(group, threads, log);
        log.progress(ProgressStage::Toolpaths, 0.0);
        const bool first_group = layers.taken() == 0;
        const auto on_counted = [&](int count) {
            if (g != last_group)
                return;
            announced = model_layers + count;
            layers.start(startText(scene, export_params, prime, *announced));
        };
        PrintPlan plan;  // outlives the streamed writer, which reads its layers
        std::optional<WrittenLayers> written;
        layers.newGroup();
        if (threads > 1 && !mixesColours(group.settings)) {  // written while later layers are planned
            StreamedWriter streamed(writer, gcode,
                                    first_group ? std::nullopt : std::optional<int>(next_index), layers);
            planGroup(scene, group, sliced, threads, state, log, plan, streamed.observer(), on_counted);
            written = streamed.finish();
        } else {
            planGroup(scene, group, sliced, threads, state, log, plan, {}, on_counted);
        }
        MixingGroup mixing_input = mixingInput(scene, group);
        mixing_input.chamber = &chamber_state;
        mixing_input.threads = effectiveThreads(threads);
        if (output.summary.min.x <= output.summary.max.x)  // the tower keeps clear of what is printed already
            mixing_input.printed_before = std::pair{Point2{output.summary.min.x, output.summary.min.y},
                                                    Point2{output.summary.max.x, output.summary.max.y}};
        mixing.add(assignMixes(plan, mixing_input, log));
        model_layers += modelLayers(plan);
        next_index = renumber(plan, next_index, first_group);
        if (on_plan)
            on_plan(plan);
        log.progress(ProgressStage::GCode, 0.8);
        if (!written)
            written = writeLayers(plan, writer, gcode, layers);
        extendBounds(output.summary, *written);
    }
    if (announced.value_or(model_layers) != model_layers)
        throw InternalError("the layer count announced to the stream (" + std::to_string(*announced) +
                            ") is not the plan's (" + std::to_string(model_layers) + ")");
    if (layers.taken() == 0) {
        output.summary.min = output.summary.max = {};
        log.warning("nothing to print: no part of " + meshNames(scene) +
                    " lies at a slice height above the build plate (0 layers)");
    }
    output.start = startText(scene, export_params, prime, model_layers);
    output.summary.extra_lines = mixing.headerLines();
    output.notes = mixing.summaryLines();
    if (!announced)
        layers.start(output.start);
    finishOutput(scene, export_params, gcode, output);
    log.progress(ProgressStage::Done, 1.0);
    return output;
}

}  // namespace mixengine
