#include "planning/TravelAreas.h"

#include <algorithm>

#include "geometry/Clip.h"

namespace mixengine {

namespace {

/// Whether the mesh's outlines are its outer walls' (see partOutlines).
bool outlinedByOuterWall(const Settings& s) {
    return s.boolean(key::support_enable) && !s.boolean(key::fill_outline_gaps) &&
           s.integer(key::wall_line_count) > 0;
}

/// The outer walls' loops grown by half their width (squared corners, as CuraEngine's print outline).
Paths outerWallOutline(const MeshLayerGroups& layer) {
    Paths loops;
    coord_um width_um = 0;
    for (const ExtrusionPath& path : layer.outer_walls) {
        if (!path.closed || path.points.size() < 3)
            continue;
        loops.push_back(path.points);
        width_um = std::max(width_um, path.width_um);
    }
    if (loops.empty())
        return {};
    const Paths area = clipAreas(loops, {}, ClipOp::Union, FillRule::EvenOdd);
    return offsetMitred(area, double(width_um) / 2, OffsetEnds::ClosedPolygon, 2.0, 25.0);
}

}  // namespace

Paths partOutlines(const GroupToolpaths& toolpaths, std::size_t layer) {
    Paths area;
    const std::size_t sliced_layer = toolpaths.first_sliced_layer + layer;
    for (const MeshToolpaths& mesh : toolpaths.meshes) {
        if (!mesh.sliced || sliced_layer >= mesh.sliced->size())
            continue;
        if (mesh.settings && outlinedByOuterWall(*mesh.settings) && layer < mesh.layers.size()) {
            const Paths outline = outerWallOutline(mesh.layers[layer]);
            area.insert(area.end(), outline.begin(), outline.end());
            continue;
        }
        const Paths& outlines = (*mesh.sliced)[sliced_layer].outlines;
        area.insert(area.end(), outlines.begin(), outlines.end());
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
