#include "toolpaths/Skin.h"

#include <algorithm>
#include <cstdlib>

#include "common/ParallelFor.h"
#include "toolpaths/LayerWindows.h"
#include "toolpaths/PolygonOps.h"

namespace mixengine {
namespace {

constexpr double kMinSkinAreaUm2 = 400.0 * 400.0;  // CuraEngine's 0.4 × 0.4 mm²

/// The skin grown by its expand distance plus the removal width left over (which the grown reference
/// regions took off it), only its parts at least min_width wide when that is set (less what the
/// removal width already removed), then clipped to the inner area: CuraEngine 4.13's expansion.
Paths expandSkin(Paths skin, coord_um preshrink, coord_um expand, coord_um min_width, const Paths& inner) {
    const coord_um half = std::max<coord_um>(0, min_width / 2 - preshrink / 2);
    const coord_um outset = expand + preshrink + half;
    if (skin.empty() || outset == 0)
        return skin;
    Paths grown = offsetMiter(half > 0 ? offsetMiter(skin, -half) : skin, outset);
    if (half > 0 || outset < 0)
        grown = unionOf(grown, skin);
    return intersectAll(grown, inner);
}

/// Each layer's reference region grown by the removal width left over, as CuraEngine 4.13 grows
/// every layer's walls before comparing: the skin loses that much along the covered area.
std::vector<Paths> grownReferences(const std::vector<Paths>& reference, coord_um by, int threads) {
    std::vector<Paths> grown(reference.size());
    parallelFor(reference.size(), threads, [&](std::size_t i) { grown[i] = offsetMiter(reference[i], by); });
    return grown;
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
    constexpr coord_um kSnapUm = 10;  // a removal width this close to a wall's centre ends there
    SkinReference ref{std::max(0, wall_count), preshrink};
    while (ref.wall > 0) {
        // From wall k's centre to wall k-1's (or, from the outer wall, to the outline).
        const coord_um here = ref.wall == 1 ? outer_width : inner_width;
        const coord_um next = ref.wall == 1 ? 0 : ref.wall == 2 ? outer_width : inner_width;
        const coord_um step = (here + next) / 2;
        if (std::abs(ref.leftover_preshrink_um - step) <= kSnapUm) {
            ref.leftover_preshrink_um = 0;
            --ref.wall;
            break;
        }
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
    const std::vector<Paths>& roof_reference = references.roofing ? *references.roofing : *references.top;
    const int n = static_cast<int>(references.top->size());
    const int roofing_layers = std::min(p.roofing_layers, p.top_layers);
    // Each layer's reference grown by the removal width left over, then intersected over the window.
    const std::vector<Paths> top_reference = grownReferences(*references.top, p.top_preshrink_um, threads);
    const std::vector<Paths> above = windowIntersections(top_reference, p.top_layers, threads);
    // Usually the same regions over the same number of layers (equal preshrink and layer counts).
    const bool same_reference =
        p.bottom_preshrink_um == p.top_preshrink_um && *references.bottom == *references.top;
    const std::vector<Paths> own_bottom_reference =
        same_reference ? std::vector<Paths>{}
                       : grownReferences(*references.bottom, p.bottom_preshrink_um, threads);
    const std::vector<Paths>& bottom_reference = same_reference ? top_reference : own_bottom_reference;
    const bool same_windows = same_reference && p.bottom_layers == p.top_layers;
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
        top = expandSkin(std::move(top), p.top_preshrink_um, p.top_expand_um, p.min_width_for_expansion_um,
                         inner);
        bottom = expandSkin(std::move(bottom), p.bottom_preshrink_um, p.bottom_expand_um,
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
