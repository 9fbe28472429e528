#include "toolpaths/InfillMeshes.h"

#include <algorithm>
#include <numeric>
#include <optional>

#include "common/ParallelFor.h"
#include "geometry/PolygonOps.h"

namespace mixengine {
namespace {

std::vector<std::size_t> meshOrder(const ToolpathInput& input) {
    std::vector<std::size_t> order(input.meshes.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return input.meshes[a].role.infill_mesh_order < input.meshes[b].role.infill_mesh_order;
    });
    return order;
}

/// The infill mesh's layers limited to the own infill of `earlier` meshes, which lose its outline.
std::vector<SlicedLayer> clipToEarlier(const std::vector<SlicedLayer>& layers,
                                       std::vector<std::optional<MeshAreas>>& areas,
                                       const std::vector<std::size_t>& earlier, int threads) {
    std::vector<SlicedLayer> clipped(layers.size());
    parallelFor(layers.size(), threads, [&](std::size_t i) {
        clipped[i].print_z = layers[i].print_z;
        clipped[i].slice_z = layers[i].slice_z;
        const Paths& outline = layers[i].outlines;
        if (outline.empty())
            return;
        Paths inside;
        for (std::size_t other : earlier) {
            if (!areas[other] || i >= areas[other]->own_infill.size())
                continue;
            Paths& own = areas[other]->own_infill[i];
            const Paths part = intersectAll(outline, own);
            inside.insert(inside.end(), part.begin(), part.end());
            own = differenceOf(own, outline);
        }
        clipped[i].outlines = unionOf(inside);
    });
    return clipped;
}

bool printsNothingHere(const VolumeRole& role) {
    return role.support_mesh || role.anti_overhang_mesh;
}

}  // namespace

std::vector<MeshToolpaths> generateModelToolpaths(const ToolpathInput& input, int threads) {
    const std::size_t n = input.meshes.size();
    std::vector<MeshToolpaths> result(n);
    std::vector<std::optional<MeshAreas>> areas(n);
    std::vector<std::vector<SlicedLayer>> clipped(n);
    const std::vector<std::size_t> order = meshOrder(input);
    std::size_t layer_steps = 0;  // walls and areas, then paths, per layer of every mesh
    for (const ToolpathMeshInput& mesh : input.meshes)
        layer_steps += printsNothingHere(mesh.role) ? 0 : 2 * mesh.layers->size();
    const WorkProgress progress(input.on_progress, layer_steps);
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t m = order[k];
        const ToolpathMeshInput& mesh = input.meshes[m];
        result[m].settings = mesh.settings;
        result[m].name = mesh.name;
        if (printsNothingHere(mesh.role)) {
            result[m].layers.resize(mesh.layers->size());
            continue;
        }
        if (mesh.role.infill_mesh) {
            const std::vector<std::size_t> earlier(order.begin(),
                                                   order.begin() + static_cast<std::ptrdiff_t>(k));
            clipped[m] = clipToEarlier(*mesh.layers, areas, earlier, threads);
        } else {
            result[m].sliced = mesh.layers;
        }
        const std::vector<SlicedLayer>& layers = mesh.role.infill_mesh ? clipped[m] : *mesh.layers;
        if (surfaceOnlyMesh(*mesh.settings))
            result[m].layers = generateMeshToolpaths(layers, *mesh.settings, threads, mesh.box_um);
        else
            areas[m] = generateMeshAreas(layers, *mesh.settings, threads, progress);
    }
    for (std::size_t m = 0; m < n; ++m) {
        if (!areas[m])
            continue;
        const ToolpathMeshInput& mesh = input.meshes[m];
        const std::vector<SlicedLayer>& layers = mesh.role.infill_mesh ? clipped[m] : *mesh.layers;
        result[m].layers =
            generateMeshPaths(std::move(*areas[m]), layers, *mesh.settings, threads, mesh.box_um, progress);
    }
    return result;
}

}  // namespace mixengine
