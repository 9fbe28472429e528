#include "toolpaths/EmptyLayers.h"

#include <algorithm>

namespace mixengine {
namespace {

bool layerEmpty(const GroupToolpaths& toolpaths, const ToolpathInput& input, std::size_t i) {
    if (i < toolpaths.support.size() && !toolpaths.support[i].empty())
        return false;
    return std::none_of(input.meshes.begin(), input.meshes.end(), [&](const ToolpathMeshInput& mesh) {
        const std::vector<SlicedLayer>& layers = *mesh.layers;
        return mesh.role.printsAlone() && i < layers.size() &&
               (!layers[i].outlines.empty() || !layers[i].open_polylines.empty());
    });
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
