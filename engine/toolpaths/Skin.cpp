#include "toolpaths/Skin.h"

#include <algorithm>

#include "common/ParallelFor.h"
#include "toolpaths/LayerWindows.h"
#include "toolpaths/PolygonOps.h"

namespace mixengine {
namespace {

constexpr double kMinSkinAreaUm2 = 400.0 * 400.0;  // CuraEngine's 0.4 × 0.4 mm²

/// Removal width (an opening by half of it), then expansion, clipped to the inner area.
Paths reshape(Paths skin, coord_um preshrink, coord_um expand, coord_um min_width, const Paths& inner) {
    if (skin.empty())
        return skin;
    if (preshrink > 0)
        skin = openPolygons(skin, preshrink / 2);
    if (expand != 0) {
        const coord_um half = min_width / 2;
        Paths grown =
            half > 0 ? offsetPolygons(offsetPolygons(skin, -half), half + expand) : offsetMiter(skin, expand);
        skin = half > 0 ? unionOf(skin, grown) : std::move(grown);
    }
    return (preshrink > 0 || expand != 0) ? intersectAll(skin, inner) : skin;
}

/// not_air for the bottom skin of layer i when the window reaches below layer 0: layers 0 … i-1.
Paths prefixIntersection(const std::vector<Paths>& present, int i) {
    Paths result = present[0];
    for (int j = 1; j < i && !result.empty(); ++j)
        result = intersectAll(result, present[static_cast<std::size_t>(j)]);
    return result;
}

/// The skin of layer i with air directly above or below it (SkinAreas::outer_surfaces).
Paths outerSurfaces(const Paths& skin, const std::vector<Paths>& reference, std::size_t i) {
    if (skin.empty())
        return {};
    Paths above = i + 1 < reference.size() ? reference[i + 1] : Paths{};
    if (i > 0)
        above = unionOf(above, differenceOf(reference[i], reference[i - 1]));
    const Paths top_most = differenceOf(skin, above);
    const Paths bottom_most = i > 0 ? differenceOf(skin, reference[i - 1]) : skin;
    return unionOf(top_most, bottom_most);
}

}  // namespace

SkinReference skinReference(coord_um preshrink, int wall_count, coord_um outer_width, coord_um inner_width) {
    SkinReference ref{std::max(0, wall_count), preshrink};
    while (ref.wall > 0) {
        // From wall k's centre to wall k-1's (or, from the outer wall, to the outline).
        const coord_um step = ref.wall == 1   ? outer_width / 2
                              : ref.wall == 2 ? outer_width / 2 + inner_width / 2
                                              : inner_width;
        if (ref.leftover_preshrink_um < step)
            break;
        ref.leftover_preshrink_um -= step;
        --ref.wall;
    }
    return ref;
}

std::vector<SkinAreas> computeSkinAreas(const SkinReferenceRegions& references,
                                        const std::vector<Paths>& inner_areas, const SkinParams& p,
                                        int threads) {
    const std::vector<Paths>& top_reference = *references.top;
    const std::vector<Paths>& bottom_reference = *references.bottom;
    const std::vector<Paths>& roof_reference = references.roofing ? *references.roofing : top_reference;
    const int n = static_cast<int>(top_reference.size());
    const int roofing_layers = std::min(p.roofing_layers, p.top_layers);
    const std::vector<Paths> above = windowIntersections(top_reference, p.top_layers, threads);
    // Usually the same regions over the same number of layers (equal preshrink and layer counts).
    const bool same_windows = p.bottom_layers == p.top_layers && bottom_reference == top_reference;
    const std::vector<Paths> own_below =
        same_windows ? std::vector<Paths>{} : windowIntersections(bottom_reference, p.bottom_layers, threads);
    const std::vector<Paths>& below = same_windows ? above : own_below;
    const std::vector<Paths> roof_above = windowIntersections(roof_reference, roofing_layers, threads);
    std::vector<SkinAreas> result(inner_areas.size());
    parallelFor(inner_areas.size(), threads, [&](std::size_t index) {
        const int i = static_cast<int>(index);
        const Paths& inner = inner_areas[index];
        if (inner.empty())
            return;
        Paths top, bottom;
        if (p.top_layers > 0)
            top = i + p.top_layers < n ? differenceOf(inner, above[index + 1]) : inner;
        if (p.bottom_layers > 0 || i < p.initial_bottom_layers) {
            if (i < p.initial_bottom_layers || i == 0)
                bottom = inner;
            else if (i - p.bottom_layers >= 0)
                bottom = differenceOf(inner, below[static_cast<std::size_t>(i - p.bottom_layers)]);
            else
                bottom = differenceOf(inner, prefixIntersection(bottom_reference, i));
        }
        top =
            reshape(std::move(top), p.top_preshrink_um, p.top_expand_um, p.min_width_for_expansion_um, inner);
        bottom = reshape(std::move(bottom), p.bottom_preshrink_um, p.bottom_expand_um,
                         p.min_width_for_expansion_um, inner);
        SkinAreas& out = result[index];
        out.skin = removeSmallIslands(unionOf(top, bottom), kMinSkinAreaUm2);
        Paths infill = differenceOf(inner, out.skin);
        if (p.infill_opening_um > 0)
            infill = openPolygons(infill, p.infill_opening_um / 2);
        out.infill = removeSmallIslands(infill, std::max(kMinSkinAreaUm2, p.min_infill_area_um2));
        if (roofing_layers > 0 && !out.skin.empty()) {
            Paths covered = i + roofing_layers < n ? roof_above[index + 1] : Paths{};
            if (i > 0)
                covered = unionOf(covered, differenceOf(roof_reference[index], roof_reference[index - 1]));
            out.roofing = differenceOf(out.skin, covered);
        }
        if (p.outer_surfaces)
            out.outer_surfaces = outerSurfaces(out.skin, roof_reference, index);
    });
    return result;
}

}  // namespace mixengine
