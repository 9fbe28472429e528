// `mixengine layers <slice arguments> -o DIR`: slice only and write what a person or a script
// wants to look at — DIR/layers.json and one SVG per layer (DIR/layer_00000.svg, ...).
//
// layers.json: slicing/SliceDump.h layersToJson, the printed meshes' outlines united per layer, in
// the model's own frame (machine_center_is_zero is forced on, so nothing is moved to the plate centre).
// Modifier meshes (infill meshes, support meshes, support blockers) are left out: they change how a
// model prints, they are not its outline. Cutting meshes are drawn, as the part of the model they took.
#include <cstdio>
#include <filesystem>

#include "common/Error.h"
#include "common/Log.h"
#include "common/ParallelFor.h"
#include "communication/CommandLineParser.h"
#include "communication/Commands.h"
#include "communication/OutputFile.h"
#include "pipeline/FffProcessor.h"
#include "slicing/SliceDump.h"

namespace mixengine {
namespace {

/// The layers of every printed mesh of a group merged into one list (outlines unioned per layer).
std::vector<SlicedLayer> mergeMeshes(const SlicedGroup& sliced) {
    std::vector<SlicedLayer> merged(sliced.heights.size());
    for (std::size_t i = 0; i < merged.size(); ++i) {
        ClipperLib::Clipper clipper;
        for (std::size_t m = 0; m < sliced.meshes.size(); ++m) {
            if (m < sliced.roles.size() && !sliced.roles[m].printsAlone())
                continue;
            const std::vector<SlicedLayer>& mesh = sliced.meshes[m];
            clipper.AddPaths(mesh[i].outlines, ClipperLib::ptSubject, true);
            merged[i].open_polylines.insert(merged[i].open_polylines.end(), mesh[i].open_polylines.begin(),
                                            mesh[i].open_polylines.end());
        }
        clipper.Execute(ClipperLib::ctUnion, merged[i].outlines, ClipperLib::pftNonZero,
                        ClipperLib::pftNonZero);
        merged[i].print_z = sliced.heights[i].print_z;
        merged[i].slice_z = sliced.heights[i].slice_z;
    }
    return merged;
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
    const Scene scene = prepareScene(request, log);
    const SceneGroup& group = scene.groups.front();
    const std::vector<SlicedLayer> layers =
        mergeMeshes(sliceGroup(group, effectiveThreads(request.threads), log, false));

    const std::filesystem::path dir = request.output;
    std::filesystem::create_directories(dir);
    std::vector<std::string> mesh_names;
    for (const SceneMesh& mesh : group.meshes)
        mesh_names.push_back(mesh.mesh.name);
    for (std::size_t i = 0; i < layers.size(); ++i) {
        char name[32];
        std::snprintf(name, sizeof name, "layer_%05zu.svg", i);
        SvgOptions svg;
        svg.caption = "layer " + std::to_string(i);
        writeFileAtomically(dir / name, layerToSvg(layers[i], svg));
    }
    writeFileAtomically(dir / "layers.json", layersToJson(layers, mesh_names));
    out << layers.size() << " layers written to " << std::filesystem::absolute(dir).string() << '\n';
    return 0;
}

}  // namespace mixengine
