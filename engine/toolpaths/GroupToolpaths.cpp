#include "toolpaths/GroupToolpaths.h"

#include <algorithm>
#include <set>

#include "common/ParallelFor.h"
#include "toolpaths/Adhesion.h"
#include "toolpaths/EmptyLayers.h"
#include "toolpaths/PolygonOps.h"
#include "toolpaths/PrimeTower.h"
#include "toolpaths/Support.h"

namespace mixengine {
namespace {

std::vector<Paths> unitedModel(const ToolpathInput& input, int threads) {
    std::vector<Paths> model(input.heights.size());
    parallelFor(model.size(), threads, [&](std::size_t i) {
        Paths all;
        for (const ToolpathMeshInput& mesh : input.meshes) {
            if (i < mesh.layers->size())
                all.insert(all.end(), (*mesh.layers)[i].outlines.begin(), (*mesh.layers)[i].outlines.end());
        }
        model[i] = input.meshes.size() > 1 ? unionOf(all) : std::move(all);
    });
    return model;
}

void collect(const std::vector<ExtrusionPath>& paths, std::set<int>& used) {
    for (const ExtrusionPath& path : paths)
        used.insert(path.extruder);
}

std::vector<std::set<int>> extrudersPerLayer(const GroupToolpaths& result, std::size_t layers) {
    std::vector<std::set<int>> used(layers);
    for (std::size_t i = 0; i < layers; ++i) {
        for (const MeshToolpaths& mesh : result.meshes) {
            if (i >= mesh.layers.size())
                continue;
            const MeshLayerGroups& g = mesh.layers[i];
            for (const auto* group : {&g.inner_walls, &g.outer_walls, &g.skin, &g.infill})
                collect(*group, used[i]);
        }
        collect(result.support[i], used[i]);
    }
    return used;
}

Paths pointsOf(const std::vector<ExtrusionPath>& paths) {
    Paths points;
    for (const ExtrusionPath& path : paths)
        points.push_back(path.points);
    return points;
}

/// Drops the empty layers at the bottom (toolpaths/EmptyLayers.h) and says so in the notes.
void dropEmptyBottomLayers(const ToolpathInput& input, GroupToolpaths& result) {
    const std::size_t empty = leadingEmptyLayers(result, input);
    if (empty == 0)
        return;
    result.notes.push_back("removing " + std::to_string(empty) +
                           " empty layer(s) at the bottom of the print");
    dropLeadingLayers(empty, result);
}

}  // namespace

GroupToolpaths generateGroupToolpaths(const ToolpathInput& input, int threads) {
    GroupToolpaths result;
    result.heights = input.heights;
    for (const ToolpathMeshInput& mesh : input.meshes) {
        MeshToolpaths paths;
        paths.settings = mesh.settings;
        paths.name = mesh.name;
        paths.sliced = mesh.layers;
        paths.layers = generateMeshToolpaths(*mesh.layers, *mesh.settings, threads);
        result.meshes.push_back(std::move(paths));
    }
    const std::vector<Paths> model = unitedModel(input, threads);

    SupportInput support{input.global, input.extruders, &input.heights, {}, &model};
    for (const ToolpathMeshInput& mesh : input.meshes)
        support.meshes.push_back({mesh.settings, mesh.layers});
    SupportResult support_result = generateSupport(support, threads);
    result.support = std::move(support_result.paths);

    std::vector<std::set<int>> used = extrudersPerLayer(result, input.heights.size());
    const TowerInput tower{input.global, input.extruders, &input.heights, used, &model};
    result.prime_tower = generatePrimeTower(tower);
    result.ooze_shield = generateOozeShield(tower);

    if (!model.empty()) {
        // As CuraEngine, the brim goes around the support on layer 0 too; around the first layer
        // that prints when the bottom ones are empty (they are dropped below).
        const std::size_t first = std::min(leadingEmptyLayers(result, input), model.size() - 1);
        AdhesionInput adhesion{input.global, input.extruders,
                               first == 0 ? unionOf(model[0], support_result.first_layer_area) : model[first],
                               pointsOf(result.support[first])};
        const Paths tower_points = pointsOf(result.prime_tower[first]);
        adhesion.extras.insert(adhesion.extras.end(), tower_points.begin(), tower_points.end());
        AdhesionResult skirt = generateAdhesion(adhesion);
        result.adhesion = std::move(skirt.paths);
        result.warnings = std::move(skirt.warnings);
    }
    dropEmptyBottomLayers(input, result);
    return result;
}

}  // namespace mixengine
