#include "toolpaths/walls/Walls.h"

#include <algorithm>
#include <iterator>

#include "geometry/PolygonOps.h"
#include "slicing/OutlineCleanup.h"
#include "toolpaths/core/FeatureStyle.h"
#include "toolpaths/walls/OutlineGaps.h"
#include "toolpaths/walls/WallOrder.h"

namespace mixengine {
namespace {

/// How far wall `i`'s centre line lies inside the previous one's (the outline's for i = 0).
coord_um insetStepUm(const WallParams& p, int i) {
    if (i == 0)
        return p.outer_width_um / 2 + p.outer_inset_um;
    if (i == 1)  // the first inner wall is placed from the outline, not from the (inset) outer wall
        return p.outer_width_um / 2 - p.outer_inset_um + p.inner_width_um / 2;
    return p.inner_width_um;
}

/// Every loop simplified as the outlines are (meshfix_maximum_resolution / _deviation); loops
/// left with fewer than three vertices go.
Paths simplifiedRegion(Paths region, const WallParams& p) {
    return simplifyLoops(std::move(region), p.simplify_resolution_um, p.simplify_deviation_um);
}

/// The wall centre regions are offsets, then simplified (meshfix_maximum_resolution / _deviation),
/// which moves no vertex off the loop by more than the deviation: they are taken as united, so the
/// next offset does not unite them again (quality.sh: coverage on armadillo52k, bunny69k and
/// rear_case as with the union).
constexpr Loops kRegionLoops = Loops::United;

/// Wall `i`'s centre region in one part, from the previous wall's (`from`, with `from_count`
/// loops; the part's outline for i = 0). As CuraEngine 4.13: a plain inward offset, so a piece
/// narrower than the line still gets its loop; when the offset breaks into more than three loops
/// more than before (more than four for the outer wall), an offset 10 µm of line width smaller is
/// taken instead if it saves more than three loops.
Paths insetRegion(const Paths& from, std::size_t from_count, int i, const WallParams& p) {
    constexpr std::size_t kMinSaving = 3;
    const coord_um step = insetStepUm(p, i);
    const Loops loops = i == 0 ? Loops::United : kRegionLoops;  // a part: an island of a union
    Paths region = offsetMiter(from, -step, loops);
    const std::size_t count = region.size();
    if (count > kMinSaving + 1 && (i == 0 || count > from_count + kMinSaving)) {
        Paths smaller = offsetMiter(from, -(step - (i <= 1 ? 5 : 10)), loops);
        if (smaller.size() + kMinSaving < count)
            region = std::move(smaller);
    }
    return simplifiedRegion(std::move(region), p);
}

/// The wall centre regions of one part (an outline with its holes), outermost first; a part too
/// thin for a wall has fewer.
std::vector<Paths> partRegions(const Paths& part, const WallParams& p) {
    std::vector<Paths> regions;
    for (int i = 0; i < p.wall_count; ++i) {
        const Paths& from = regions.empty() ? part : regions.back();
        Paths region = insetRegion(from, from.size(), i, p);
        if (region.empty())
            break;
        regions.push_back(std::move(region));
    }
    return regions;
}

/// Wall k's centre region (k ≥ 1; 0 = the outline: the parts one after the other, a union) where
/// parts with fewer walls use their innermost one: regions[k-1], plus what of the outer region lies
/// farther than k's depth from it.
Paths referenceRegion(const std::vector<Paths>& parts, const std::vector<Paths>& regions,
                      const std::vector<coord_um>& depths, int k) {
    if (k <= 0 || regions.empty()) {
        Paths united;
        for (const Paths& part : parts)
            united.insert(united.end(), part.begin(), part.end());
        return united;
    }
    const std::size_t last = static_cast<std::size_t>(std::min<int>(k, static_cast<int>(regions.size()))) - 1;
    if (last == 0)
        return regions[0];
    return unionOf(regions[last],
                   differenceOf(regions[0], offsetMiter(regions[last], depths[last] + 10, kRegionLoops)));
}

FeatureStyle levelStyle(const WallParams& p, std::size_t level) {
    return level == 0 ? FeatureStyle{p.outer_width_um, p.outer_speed_mm_s, p.outer_flow, p.outer_extruder}
                      : FeatureStyle{p.inner_width_um, p.inner_speed_mm_s, p.inner_flow, p.inner_extruder};
}

/// The loops of every level as paths: level by level, or grouped by outline (WallParams).
std::vector<ExtrusionPath> wallPaths(const std::vector<Paths>& levels, const std::vector<coord_um>& depths,
                                     const WallParams& p) {
    std::vector<ExtrusionPath> out;
    if (levels.empty())
        return out;
    if (!p.group_by_outline) {
        for (std::size_t k = 0; k < levels.size(); ++k)
            appendStyledLoops(levels[k], k == 0 ? Feature::WallOuter : Feature::WallInner, levelStyle(p, k),
                              out);
        return out;
    }
    std::vector<coord_um> steps(depths.size(), 0);
    for (std::size_t k = 1; k < depths.size(); ++k)
        steps[k] = depths[k] - depths[k - 1];
    const std::vector<std::vector<std::size_t>> families = wallFamilies(levels, steps);
    auto appendLevel = [&](std::size_t k) {
        for (std::size_t i = 0; i < levels[k].size(); ++i) {
            if (levels[k][i].size() < 3)
                continue;
            out.push_back(styledPath(levels[k][i], true, k == 0 ? Feature::WallOuter : Feature::WallInner,
                                     levelStyle(p, k)));
            out.back().sequence = static_cast<std::uint32_t>(families[k][i] + 1);
        }
    };
    appendLevel(0);
    for (std::size_t n = 1; n < levels.size(); ++n)
        appendLevel(p.outer_first ? n : levels.size() - n);
    return out;
}

/// The gaps between consecutive walls (WallResult::perimeter_gaps); inside the innermost wall too
/// when no part has all its walls (nothing else fills it then).
Paths gapsBetweenWalls(const std::vector<Paths>& levels, const WallParams& p) {
    constexpr coord_um kSlackUm = 15;  // CuraEngine's: no gaps everywhere from rounding
    const bool walls_missing = static_cast<int>(levels.size()) < p.wall_count;
    // Inside the innermost wall go skin and infill, and their gaps (MeshToolpaths), unless walls are missing.
    const std::size_t terms = walls_missing ? levels.size() : levels.size() - 1;
    const double min_area_um2 =
        p.filter_tiny_gaps ? 2.0 * double(p.outer_width_um) * double(p.outer_width_um) : 0;
    // Gap k: what of wall k's inside edge (less the slack) wall k + 1 does not reach.
    auto gapTerms = [&](std::size_t k) {
        const coord_um width = k == 0 ? p.outer_width_um : p.inner_width_um;
        std::pair<Paths, Paths> outer_inner{offsetMiter(levels[k], -width / 2 - kSlackUm, kRegionLoops), {}};
        if (k + 1 < levels.size())
            outer_inner.second = offsetMiter(levels[k + 1], p.inner_width_um / 2, kRegionLoops);
        return outer_inner;
    };
    if (terms == 1) {  // the usual case, two walls: one pass
        const auto [outer, inner] = gapTerms(0);
        return differenceWithoutSmallIslands(outer, inner, min_area_um2);
    }
    Paths gaps;
    for (std::size_t k = 0; k < terms; ++k) {
        const auto [outer, inner] = gapTerms(k);
        gaps = gaps.empty() ? differenceOf(outer, inner) : unionOf(gaps, differenceOf(outer, inner));
    }
    return removeSmallIslands(gaps, min_area_um2);
}

}  // namespace

WallResult generateWalls(const Paths& outlines, const WallParams& params) {
    WallResult result;
    result.parts = splitIslands(outlines);
    if (params.wall_count <= 0) {
        result.inner_area = result.top_reference = result.bottom_reference = unionOf(outlines);
        if (params.roofing_reference >= 0)
            result.roofing_reference = result.top_reference;
        return result;
    }
    const std::vector<Paths>& parts = result.parts;
    std::vector<Paths> regions;    // centre region of each wall that exists somewhere
    std::vector<coord_um> depths;  // its distance inside the outer wall's centre line
    for (const Paths& part : parts) {
        std::vector<Paths> own = partRegions(part, params);
        for (std::size_t k = 0; k < own.size(); ++k) {
            if (k == regions.size()) {
                regions.emplace_back();
                depths.push_back(k == 0 ? 0 : depths.back() + insetStepUm(params, static_cast<int>(k)));
            }
            std::move(own[k].begin(), own[k].end(), std::back_inserter(regions[k]));
        }
    }
    // Skin and infill go inside the innermost wall where some part has all its walls.
    const bool all_walls = static_cast<int>(regions.size()) == params.wall_count;
    const Paths region = all_walls ? regions.back() : Paths{};
    const coord_um last_half = (params.wall_count == 1 ? params.outer_width_um : params.inner_width_um) / 2;
    result.walls = wallPaths(regions, depths, params);
    if (params.perimeter_gaps)
        result.perimeter_gaps = gapsBetweenWalls(regions, params);
    if (params.outline_gaps)
        result.outline_gaps = outlineGaps(outlines, regions.empty() ? Paths{} : regions[0],
                                          params.outer_width_um, params.outer_inset_um);
    result.inner_area = region.empty() ? Paths{} : offsetMiter(region, -last_half, kRegionLoops);
    result.top_reference = referenceRegion(parts, regions, depths, params.top_reference);
    result.bottom_reference = params.bottom_reference == params.top_reference
                                  ? result.top_reference
                                  : referenceRegion(parts, regions, depths, params.bottom_reference);
    if (params.roofing_reference >= 0)
        result.roofing_reference = referenceRegion(parts, regions, depths, params.roofing_reference);
    if (!regions.empty())
        result.outer_region = regions[0];
    return result;
}

}  // namespace mixengine
