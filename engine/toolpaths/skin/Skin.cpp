#include "toolpaths/skin/Skin.h"

#include <algorithm>
#include <cstdlib>

#include "common/ParallelFor.h"
#include "geometry/Clip.h"
#include "geometry/PolygonOps.h"
#include "toolpaths/core/LayerWindows.h"

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
    // The skin is the inner area (united, WallResult) or a difference from it.
    Paths grown =
        offsetMiter(half > 0 ? offsetMiter(skin, -half, Loops::United) : skin, outset, Loops::United);
    if (half > 0 || outset < 0)
        grown = unionOf(grown, skin);
    return intersectAll(grown, inner);
}

/// Each layer's reference region grown by the removal width left over, as CuraEngine 4.13 grows
/// every layer's walls before comparing: the skin loses that much along the covered area.
std::vector<Paths> grownReferences(const std::vector<Paths>& reference, coord_um by, int threads) {
    std::vector<Paths> grown(reference.size());
    // The references are united (WallResult): no union before the offset.
    parallelFor(reference.size(), threads,
                [&](std::size_t i) { grown[i] = offsetMiter(reference[i], by, Loops::United); });
    return grown;
}

/// inner less what covers it; with min_infill_area, the covering pieces under it do not count.
Paths uncovered(const Paths& inner, const Paths& covered, double min_area_um2) {
    if (min_area_um2 > 0)
        return differenceOf(inner, removeSmallOutlines(covered, min_area_um2));
    return differenceOf(inner, covered);
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

enum class WindowEnd { First, Last };

/// result[i] covers layers i … i + window − 1 (empty past the last layer): their intersection, or
/// with skin_no_small_gaps_heuristic only the layer at the window's far end from the skin (its
/// last layer for the top skin, its first for the bottom skin), as CuraEngine 4.13 takes it.
std::vector<Paths> windowCover(const std::vector<Paths>& layers, int window, bool heuristic, WindowEnd end,
                               int threads) {
    if (!heuristic || window <= 1)
        return windowIntersections(layers, window, threads);
    const std::size_t w = static_cast<std::size_t>(window);
    std::vector<Paths> result(layers.size());
    for (std::size_t i = 0; i + w <= layers.size(); ++i)
        result[i] = layers[end == WindowEnd::Last ? i + w - 1 : i];
    return result;
}

/// What every layer's skin is compared with: the reference regions grown by the removal width left
/// over, and what covers them over the top, bottom and roofing windows (windowCover). The bottom
/// ones are usually the top ones (same regions, preshrink and count, no heuristic).
class Windows {
  public:
    Windows(const SkinReferenceRegions& references, const SkinParams& p, int threads)
        : same_reference_(p.bottom_preshrink_um == p.top_preshrink_um &&
                          *references.bottom == *references.top),
          same_windows_(same_reference_ && p.bottom_layers == p.top_layers && !p.small_gaps_heuristic),
          roof_reference_(references.roofing ? *references.roofing : *references.top),
          top_reference_(grownReferences(*references.top, p.top_preshrink_um, threads)),
          above_(windowCover(top_reference_, p.top_layers, p.small_gaps_heuristic, WindowEnd::Last, threads)),
          roof_above_(windowCover(roof_reference_, std::min(p.roofing_layers, p.top_layers),
                                  p.small_gaps_heuristic, WindowEnd::Last, threads)) {
        if (!same_reference_)
            own_bottom_reference_ = grownReferences(*references.bottom, p.bottom_preshrink_um, threads);
        if (!same_windows_)
            own_below_ = windowCover(bottomReference(), p.bottom_layers, p.small_gaps_heuristic,
                                     WindowEnd::First, threads);
    }
    const std::vector<Paths>& above() const { return above_; }
    const std::vector<Paths>& below() const { return same_windows_ ? above_ : own_below_; }
    const std::vector<Paths>& bottomReference() const {
        return same_reference_ ? top_reference_ : own_bottom_reference_;
    }
    const std::vector<Paths>& roofReference() const { return roof_reference_; }
    const std::vector<Paths>& roofAbove() const { return roof_above_; }

  private:
    bool same_reference_, same_windows_;
    const std::vector<Paths>& roof_reference_;
    std::vector<Paths> top_reference_, above_, roof_above_, own_bottom_reference_, own_below_;
};

Paths topSkin(const Windows& w, const Paths& inner, int i, int n, const SkinParams& p) {
    if (p.top_layers <= 0)
        return {};
    if (i + p.top_layers >= n)
        return inner;
    return uncovered(inner, w.above()[static_cast<std::size_t>(i + 1)], p.min_infill_area_um2);
}

Paths bottomSkin(const Windows& w, const Paths& inner, int i, const SkinParams& p) {
    if (p.bottom_layers <= 0 && i >= p.initial_bottom_layers)
        return {};
    if (i < p.initial_bottom_layers || i == 0)
        return inner;
    if (i >= p.bottom_layers)
        return uncovered(inner, w.below()[static_cast<std::size_t>(i - p.bottom_layers)],
                         p.min_infill_area_um2);
    const Paths& reference_0 = w.bottomReference()[0];
    if (p.small_gaps_heuristic)  // the window's first layer: layer 0
        return uncovered(inner, reference_0, p.min_infill_area_um2);
    return uncovered(inner, prefixIntersection(w.bottomReference(), i), p.min_infill_area_um2);
}

/// The part of the skin with air within roofing_layers above (none where the roofing reference has
/// nothing of it on the layer below).
Paths roofingOf(const Paths& skin, const Windows& w, int i, int n, int roofing_layers) {
    const std::size_t index = static_cast<std::size_t>(i);
    Paths covered = i + roofing_layers < n ? w.roofAbove()[index + 1] : Paths{};
    if (i > 0)
        covered = unionOf(covered, differenceOf(w.roofReference()[index], w.roofReference()[index - 1]));
    return differenceOf(skin, covered);
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
    const int n = static_cast<int>(references.top->size());
    const int roofing_layers = std::min(p.roofing_layers, p.top_layers);
    const Windows windows(references, p, threads);
    std::vector<SkinAreas> result(inner_areas.size());
    parallelFor(inner_areas.size(), threads, [&](std::size_t index) {
        const int i = static_cast<int>(index);
        const Paths& inner = inner_areas[index];
        if (inner.empty())
            return;
        const Paths top = expandSkin(topSkin(windows, inner, i, n, p), p.top_preshrink_um, p.top_expand_um,
                                     p.min_width_for_expansion_um, inner);
        const Paths bottom = expandSkin(bottomSkin(windows, inner, i, p), p.bottom_preshrink_um,
                                        p.bottom_expand_um, p.min_width_for_expansion_um, inner);
        SkinAreas& out = result[index];
        out.skin = removeSmallOutlines(unionOf(top, bottom), kMinSkinAreaUm2);
        Paths infill = out.skin.empty() ? inner : differenceOf(inner, out.skin);  // inner: united
        if (p.infill_opening_um > 0)
            infill = openPolygons(infill, p.infill_opening_um / 2, Loops::United);  // a difference: united
        out.infill = removeSmallOutlines(infill, kMinSkinAreaUm2);
        if (roofing_layers > 0 && !out.skin.empty())
            out.roofing = roofingOf(out.skin, windows, i, n, roofing_layers);
        if (p.outer_surfaces)
            out.outer_surfaces = outerSurfaces(out.skin, windows.roofReference(), index);
    });
    return result;
}

}  // namespace mixengine
