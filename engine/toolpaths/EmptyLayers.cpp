#include "toolpaths/EmptyLayers.h"

#include <algorithm>

namespace mixengine {
namespace {

/// Whether mesh `k` prints something of its own on layer i: its open pieces, or (as CuraEngine drops a
/// part too thin for a wall before it counts the empty first layers) a path of its toolpaths.
bool meshPrints(const GroupToolpaths& toolpaths, const ToolpathInput& input, std::size_t k, std::size_t i) {
    const ToolpathMeshInput& mesh = input.meshes[k];
    const std::vector<SlicedLayer>& layers = *mesh.layers;
    if (!mesh.role.printsAlone() || i >= layers.size())
        return false;
    if (!layers[i].open_polylines.empty())
        return true;
    if (k >= toolpaths.meshes.size() || i >= toolpaths.meshes[k].layers.size())
        return !layers[i].outlines.empty();
    const MeshLayerGroups& groups = toolpaths.meshes[k].layers[i];
    return !groups.outer_walls.empty() || !groups.inner_walls.empty() || !groups.skin.empty() ||
           !groups.infill.empty();
}

bool layerEmpty(const GroupToolpaths& toolpaths, const ToolpathInput& input, std::size_t i) {
    if (i < toolpaths.support.size() && !toolpaths.support[i].empty())
        return false;
    for (std::size_t k = 0; k < input.meshes.size(); ++k) {
        if (meshPrints(toolpaths, input, k, i))
            return false;
    }
    return true;
}

template <typename T>
void dropFront(std::vector<T>& list, std::size_t count) {
    list.erase(list.begin(), list.begin() + static_cast<std::ptrdiff_t>(std::min(count, list.size())));
}

}  // namespace

std::size_t leadingEmptyLayers(const GroupToolpaths& toolpaths, const ToolpathInput& input) {
    std::size_t layers = 0;
    for (const ToolpathMeshInput& mesh : input.meshes)
        layers = std::max(layers, mesh.layers->size());
    std::size_t count = 0;
    while (count < layers && layerEmpty(toolpaths, input, count))
        ++count;
    return count;  // all of them when nothing prints (a flat or floating facet): 0 layers, as CuraEngine
}

void dropLeadingLayers(std::size_t count, GroupToolpaths& toolpaths) {
    if (count == 0)
        return;
    for (MeshToolpaths& mesh : toolpaths.meshes)
        dropFront(mesh.layers, count);
    dropFront(toolpaths.support, count);
    dropFront(toolpaths.prime_tower, count);
    if (toolpaths.prime_tower_last_forced_layer >= 0)
        toolpaths.prime_tower_last_forced_layer -= static_cast<int>(count);
    dropFront(toolpaths.ooze_shield, count);
    dropFront(toolpaths.draft_shield, count);
    toolpaths.heights.resize(toolpaths.heights.size() - std::min(count, toolpaths.heights.size()));
    toolpaths.first_sliced_layer += count;
}

}  // namespace mixengine
