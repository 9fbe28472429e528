// `mixengine layers <slice arguments> -o DIR`: slice only and write what a person or a script
// wants to look at — DIR/layers.json and one SVG per layer (DIR/layer_00000.svg, ...).
//
// layers.json: slicing/SliceDump.h layersToJson, the printed meshes' outlines united per layer, in
// the model's own frame (machine_center_is_zero is forced on, so nothing is moved to the plate centre).
// Modifier meshes (infill meshes, support meshes, support blockers) are left out: they change how a
// model prints, they are not its outline. Cutting meshes are drawn, as the part of the model they took.
//
// A mixing print (mixing_mode not single; issue 26) is also run through the whole pipeline, as
// `slice` runs it, and each layer's SVG draws that layer's extrusions over its outline, as lines of
// their width in the colour predicted to leave the nozzle (communication/LayerColours.h); layers.json
// gains, per layer, the ;LAYER: number that prints it and the colours with the length printed in
// each, and the raft's layers, which no sliced layer stands for. The planned layers are matched to
// the sliced ones by their ;LAYER: number: planned layer n prints sliced layer n + d, where d is the
// number of empty bottom layers the toolpath stage drops (toolpaths/EmptyLayers.h; almost always 0),
// i.e. the sliced layers less the planned model layers. Only the first mesh group is drawn (as ever);
// only it is planned. A single-colour print is written exactly as before.
#include <cstdio>
#include <filesystem>
#include <optional>
#include <sstream>

#include "common/Error.h"
#include "common/Log.h"
#include "common/ParallelFor.h"
#include "communication/CommandLineParser.h"
#include "communication/Commands.h"
#include "communication/LayerColours.h"
#include "communication/OutputFile.h"
#include "geometry/Clip.h"
#include "mixing/setup/MixingSettings.h"
#include "pipeline/FffProcessor.h"
#include "slicing/SliceDump.h"

namespace mixengine {
namespace {

/// The layers of every printed mesh of a group merged into one list (outlines unioned per layer).
std::vector<SlicedLayer> mergeMeshes(const SlicedGroup& sliced) {
    std::vector<SlicedLayer> merged(sliced.heights.size());
    for (std::size_t i = 0; i < merged.size(); ++i) {
        Paths outlines;  // every printed mesh's loops, in mesh order
        for (std::size_t m = 0; m < sliced.meshes.size(); ++m) {
            if (m < sliced.roles.size() && !sliced.roles[m].printsAlone())
                continue;
            const std::vector<SlicedLayer>& mesh = sliced.meshes[m];
            outlines.insert(outlines.end(), mesh[i].outlines.begin(), mesh[i].outlines.end());
            merged[i].open_polylines.insert(merged[i].open_polylines.end(), mesh[i].open_polylines.begin(),
                                            mesh[i].open_polylines.end());
        }
        merged[i].outlines = clipAreas(outlines, {}, ClipOp::Union, FillRule::NonZero);
        merged[i].print_z = sliced.heights[i].print_z;
        merged[i].slice_z = sliced.heights[i].slice_z;
    }
    return merged;
}

/// The first group's plan, in the colours predicted to leave the nozzle.
struct PrintedColours {
    std::vector<ColouredLayer> layers;  ///< every planned layer, the raft's first
    std::vector<Rgb8> colors;           ///< PrintPlan::outlet_colors
};

/// Runs the pipeline on the first group alone (the G-code is not kept); the mixing report goes to `err`.
PrintedColours planColours(Scene& scene, int threads, Log& log, std::ostream& err) {
    if (scene.groups.size() > 1)
        scene.groups.erase(scene.groups.begin() + 1, scene.groups.end());
    PrintedColours result;
    bool seen = false;
    const PlanObserver observe = [&](const PrintPlan& plan) {
        if (seen)
            throw InternalError("layers: more than one plan for one mesh group");
        seen = true;
        result.layers = colouredLayers(plan);
        result.colors = plan.outlet_colors;
    };
    const GCodeOutput gcode = runPipeline(scene, threads, log, observe);
    for (const std::string& note : gcode.notes)
        err << note << '\n';
    return result;
}

struct LayerMatch {
    std::vector<const ColouredLayer*> printed;  ///< [sliced layer] the planned layer printing it, or null
    std::vector<const ColouredLayer*> raft;
};

/// Planned layer n (n ≥ 0) prints sliced layer n + d, d the empty bottom layers dropped (see above).
LayerMatch matchLayers(const std::vector<ColouredLayer>& planned, std::size_t sliced) {
    LayerMatch match;
    match.printed.assign(sliced, nullptr);
    std::size_t model = 0;
    for (const ColouredLayer& layer : planned) {
        if (layer.index < 0)
            match.raft.push_back(&layer);
        else
            ++model;
    }
    if (model > sliced)
        throw InternalError("layers: the plan has " + std::to_string(model) +
                            " model layers, the slices only " + std::to_string(sliced));
    const std::size_t dropped = sliced - model;
    for (const ColouredLayer& layer : planned) {
        const std::size_t at = static_cast<std::size_t>(layer.index) + dropped;
        if (layer.index >= 0 && at < sliced)
            match.printed[at] = &layer;
    }
    return match;
}

std::string svgName(std::size_t index) {
    char name[32];
    std::snprintf(name, sizeof name, "layer_%05zu.svg", index);
    return name;
}

SvgOptions svgOptions(std::size_t index) {
    SvgOptions svg;
    svg.caption = "layer " + std::to_string(index);
    return svg;
}

void writeOutlines(const std::filesystem::path& dir, const std::vector<SlicedLayer>& layers,
                   const std::vector<std::string>& mesh_names) {
    for (std::size_t i = 0; i < layers.size(); ++i)
        writeFileAtomically(dir / svgName(i), layerToSvg(layers[i], svgOptions(i)));
    writeFileAtomically(dir / "layers.json", layersToJson(layers, mesh_names));
}

void writeColoured(const std::filesystem::path& dir, const std::vector<SlicedLayer>& layers,
                   const std::vector<std::string>& mesh_names, const PrintedColours& colours) {
    const LayerMatch match = matchLayers(colours.layers, layers.size());
    for (std::size_t i = 0; i < layers.size(); ++i)
        writeFileAtomically(dir / svgName(i),
                            colouredLayerSvg(layers[i], match.printed[i], colours.colors, svgOptions(i)));
    writeFileAtomically(dir / "layers.json",
                        colouredLayersToJson(layers, mesh_names, match.printed, match.raft, colours.colors));
}

}  // namespace

int runLayersCommand(const Words& args, std::ostream& out, std::ostream& err) {
    ParsedSliceArgs parsed = parseSliceArguments(args);
    SliceRequest& request = parsed.request;
    if (request.output.empty())
        throw InputError("layers: give the output folder with -o DIR");
    request.user.global["machine_center_is_zero"] = "True";
    Log log(err, request.verbosity);
    log.setProgress(request.progress);
    Scene scene = prepareScene(request, log);
    const int threads = effectiveThreads(request.threads);
    const bool mixing = parseMixingOutput(scene.groups.front().settings).enabled();
    std::optional<PrintedColours> colours;
    if (mixing)
        colours = planColours(scene, threads, log, err);
    // A mixing print's pipeline has already reported what slicing found: the raw slices stay quiet.
    std::ostringstream quiet_sink;
    Log quiet(quiet_sink);
    const SceneGroup& group = scene.groups.front();
    const std::vector<SlicedLayer> layers =
        mergeMeshes(sliceGroup(group, threads, mixing ? quiet : log, false));

    const std::filesystem::path dir = request.output;
    std::filesystem::create_directories(dir);
    std::vector<std::string> mesh_names;
    for (const SceneMesh& mesh : group.meshes)
        mesh_names.push_back(mesh.mesh.name);
    if (colours)
        writeColoured(dir, layers, mesh_names, *colours);
    else
        writeOutlines(dir, layers, mesh_names);
    out << layers.size() << " layers written to " << std::filesystem::absolute(dir).string() << '\n';
    return 0;
}

}  // namespace mixengine
