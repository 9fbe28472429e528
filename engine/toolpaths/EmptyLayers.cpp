#include "toolpaths/EmptyLayers.h"

#include <algorithm>

namespace mixengine {
namespace {

bool layerEmpty(const GroupToolpaths& toolpaths, const ToolpathInput& input, std::size_t i) {
    if (i < toolpaths.support.size() && !toolpaths.support[i].empty())
        return false;
    return std::none_of(input.meshes.begin(), input.meshes.end(), [&](const ToolpathMeshInput& mesh) {
        const std::vector<SlicedLayer>& layers = *mesh.layers;
        return i < layers.size() && (!layers[i].outlines.empty() || !layers[i].open_polylines.empty());
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
    dropFront(toolpaths.ooze_shield, count);
    toolpaths.heights.resize(toolpaths.heights.size() - std::min(count, toolpaths.heights.size()));
    toolpaths.first_sliced_layer += count;
}

namespace {

bool nothingPrints(const GroupToolpaths& toolpaths, std::size_t i) {
    const auto empty = [i](const std::vector<std::vector<ExtrusionPath>>& per_layer) {
        return i >= per_layer.size() || per_layer[i].empty();
    };
    if (!empty(toolpaths.support) || !empty(toolpaths.prime_tower) || !empty(toolpaths.ooze_shield))
        return false;
    return std::all_of(toolpaths.meshes.begin(), toolpaths.meshes.end(), [i](const MeshToolpaths& mesh) {
        if (i >= mesh.layers.size())
            return true;
        const MeshLayerGroups& g = mesh.layers[i];
        return g.inner_walls.empty() && g.outer_walls.empty() && g.skin.empty() && g.infill.empty();
    });
}

template <typename T>
void dropBack(std::vector<T>& list, std::size_t keep) {
    if (list.size() > keep)
        list.resize(keep);
}

}  // namespace

std::size_t trailingEmptyLayers(const GroupToolpaths& toolpaths) {
    std::size_t count = 0;
    const std::size_t layers = toolpaths.heights.size();
    while (count < layers && layers - count - 1 > 0 && nothingPrints(toolpaths, layers - count - 1))
        ++count;
    return count;
}

void dropTrailingLayers(std::size_t count, GroupToolpaths& toolpaths) {
    if (count == 0)
        return;
    const std::size_t keep = toolpaths.heights.size() - std::min(count, toolpaths.heights.size());
    for (MeshToolpaths& mesh : toolpaths.meshes)
        dropBack(mesh.layers, keep);
    dropBack(toolpaths.support, keep);
    dropBack(toolpaths.prime_tower, keep);
    dropBack(toolpaths.ooze_shield, keep);
    dropBack(toolpaths.heights, keep);
}

}  // namespace mixengine
