#include "pipeline/EmptyLayers.h"

#include <algorithm>

namespace mixengine {
namespace {

bool layerEmpty(const GroupToolpaths& toolpaths, const std::vector<std::vector<SlicedLayer>>& meshes,
                std::size_t i) {
    if (i < toolpaths.support.size() && !toolpaths.support[i].empty())
        return false;
    return std::none_of(meshes.begin(), meshes.end(), [&](const auto& layers) {
        return i < layers.size() && (!layers[i].outlines.empty() || !layers[i].open_polylines.empty());
    });
}

template <typename T>
void dropFront(std::vector<T>& list, std::size_t count) {
    list.erase(list.begin(), list.begin() + static_cast<std::ptrdiff_t>(std::min(count, list.size())));
}

}  // namespace

std::size_t leadingEmptyLayers(const GroupToolpaths& toolpaths,
                               const std::vector<std::vector<SlicedLayer>>& meshes) {
    std::size_t layers = 0;
    for (const auto& mesh : meshes)
        layers = std::max(layers, mesh.size());
    std::size_t count = 0;
    while (count < layers && layerEmpty(toolpaths, meshes, count))
        ++count;
    return count;  // all of them when nothing prints (a flat or floating facet): 0 layers, as CuraEngine
}

void dropLeadingLayers(std::size_t count, GroupToolpaths& toolpaths, std::vector<LayerZ>& heights,
                       std::vector<Paths>& comb_areas) {
    if (count == 0)
        return;
    for (MeshToolpaths& mesh : toolpaths.meshes)
        dropFront(mesh.layers, count);
    dropFront(toolpaths.support, count);
    dropFront(toolpaths.prime_tower, count);
    dropFront(toolpaths.ooze_shield, count);
    dropFront(comb_areas, count);
    heights.resize(heights.size() - std::min(count, heights.size()));
}

}  // namespace mixengine
