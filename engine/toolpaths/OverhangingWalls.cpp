#include "toolpaths/OverhangingWalls.h"

#include <algorithm>

#include "common/ParallelFor.h"
#include "geometry/PolygonOps.h"
#include "toolpaths/walls/OverhangWalls.h"

namespace mixengine {
namespace {

/// The layer parts of `mesh` on `layer`, as one area.
Paths partsOf(const MeshToolpaths& mesh, std::size_t layer) {
    Paths area;
    if (layer < mesh.layers.size()) {
        for (const Paths& part : mesh.layers[layer].parts)
            area.insert(area.end(), part.begin(), part.end());
    }
    return area;
}

/// What carries layer `layer` (`thickness_um` thick) of a mesh with settings `s`: every mesh's parts on
/// the layer below, and the support under the model (see the header).
Paths layerBelow(const Settings& global, const Settings& s, const std::vector<SupportLayerAreas>& support,
                 const std::vector<MeshToolpaths>& meshes, std::size_t layer, coord_um thickness_um) {
    Paths below;
    for (const MeshToolpaths& other : meshes) {
        const Paths parts = partsOf(other, layer - 1);
        below.insert(below.end(), parts.begin(), parts.end());
    }
    if (global.boolean(key::support_enable)) {
        const coord_um layer_height = std::max<coord_um>(1, thickness_um);
        const coord_um top_distance = std::max<coord_um>(0, s.lengthMicrons(key::support_top_distance));
        const std::size_t gap =
            static_cast<std::size_t>((top_distance + layer_height - 1) / layer_height) + 1;
        if (layer > gap && layer - gap < support.size()) {
            const SupportLayerAreas& under = support[layer - gap];
            const Paths& carrying = under.roof.empty() ? under.support : under.roof;
            below.insert(below.end(), carrying.begin(), carrying.end());
        }
    }
    return below.empty() ? below : unionOf(below);
}

}  // namespace

void markOverhangingWallsOfGroup(const Settings& global, const std::vector<LayerZ>& heights,
                                 const std::vector<SupportLayerAreas>& support,
                                 std::vector<MeshToolpaths>& meshes, int threads) {
    if (global.boolean(key::magic_spiralize))
        return;
    for (MeshToolpaths& mesh : meshes) {
        if (mesh.settings == nullptr)
            continue;
        const OverhangWallParams params = overhangWallParams(*mesh.settings);
        if (!params.enabled)
            continue;
        const std::size_t count = std::min(mesh.layers.size(), heights.size());
        parallelFor(count, threads, [&](std::size_t i) {
            MeshLayerGroups& layer = mesh.layers[i];
            if (i == 0 || (layer.outer_walls.empty() && layer.inner_walls.empty()))
                return;
            const coord_um thickness = i == 1 ? mesh.settings->lengthMicrons(key::layer_height)
                                              : heights[i].print_z - heights[i - 1].print_z;
            const Paths outlines = partsOf(mesh, i);
            const Paths below = layerBelow(global, *mesh.settings, support, meshes, i, thickness);
            const Paths mask = overhangWallMask(outlines, below, thickness, params);
            markOverhangingWalls(layer.outer_walls, mask, params);
            markOverhangingWalls(layer.inner_walls, mask, params);
        });
    }
}

}  // namespace mixengine
