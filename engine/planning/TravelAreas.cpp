#include "planning/TravelAreas.h"

#include <algorithm>

namespace mixengine {

Paths partOutlines(const GroupToolpaths& toolpaths, std::size_t layer) {
    Paths area;
    const std::size_t sliced_layer = toolpaths.first_sliced_layer + layer;
    for (const MeshToolpaths& mesh : toolpaths.meshes) {
        if (mesh.sliced && sliced_layer < mesh.sliced->size()) {
            const Paths& outlines = (*mesh.sliced)[sliced_layer].outlines;
            area.insert(area.end(), outlines.begin(), outlines.end());
        }
    }
    return area;
}

Paths combArea(const GroupToolpaths& toolpaths, std::size_t layer) {
    Paths area;
    const std::size_t sliced_layer = toolpaths.first_sliced_layer + layer;
    for (const MeshToolpaths& mesh : toolpaths.meshes) {
        const Paths* part = nullptr;
        if (layer < mesh.layers.size() && mesh.layers[layer].comb_area)
            part = &*mesh.layers[layer].comb_area;
        else if (mesh.sliced && sliced_layer < mesh.sliced->size())
            part = &(*mesh.sliced)[sliced_layer].outlines;
        if (part)
            area.insert(area.end(), part->begin(), part->end());
    }
    return area;
}

Paths freeSpace(const Paths& outlines, coord_um avoid_distance_um, Loops loops) {
    if (outlines.empty())
        return {};
    Paths free = offsetMiter(outlines, avoid_distance_um, loops);  // as 4.13's Comb: united, mitred
    const Box2 box = boundsOf(free);
    constexpr coord_um kMarginUm = 5'000;
    free.insert(free.begin(), Path{{box.left - kMarginUm, box.top - kMarginUm},
                                   {box.right + kMarginUm, box.top - kMarginUm},
                                   {box.right + kMarginUm, box.bottom + kMarginUm},
                                   {box.left - kMarginUm, box.bottom + kMarginUm}});
    return free;
}

LayerBoundaries layerBoundaries(const GroupToolpaths& toolpaths, std::size_t i, coord_um avoid_distance_um) {
    const std::size_t sliced_layer = toolpaths.first_sliced_layer + i;
    const auto has_layer = [&](const MeshToolpaths& mesh) {
        return mesh.sliced && sliced_layer < mesh.sliced->size() &&
               !(*mesh.sliced)[sliced_layer].outlines.empty();
    };
    const bool one_mesh = std::count_if(toolpaths.meshes.begin(), toolpaths.meshes.end(), has_layer) <= 1;
    return {CombBoundary(combArea(toolpaths, i)),
            CombBoundary(freeSpace(partOutlines(toolpaths, i), avoid_distance_um,
                                   one_mesh ? Loops::United : Loops::Any))};
}

}  // namespace mixengine
