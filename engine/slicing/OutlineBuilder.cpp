#include "slicing/OutlineBuilder.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "geometry/Clip.h"

namespace mixengine {
namespace {

struct Box {
    coord_um min_x, min_y, max_x, max_y;
    bool contains(const Box& o) const {
        return min_x <= o.min_x && min_y <= o.min_y && max_x >= o.max_x && max_y >= o.max_y;
    }
};

struct LoopInfo {
    const StitchedPath* loop;
    double area_um2;  ///< signed, of the loop as traversed
    Box box;
};

Box boundingBox(const Path& path) {
    Box box{path.front().X, path.front().Y, path.front().X, path.front().Y};
    for (const Point2& p : path) {
        box = {std::min(box.min_x, p.X), std::min(box.min_y, p.Y), std::max(box.max_x, p.X),
               std::max(box.max_y, p.Y)};
    }
    return box;
}

/// Whether `inner` lies inside `outer`, judged on the first vertex not on outer's boundary.
bool containsLoop(const LoopInfo& outer, const LoopInfo& inner) {
    if (!outer.box.contains(inner.box))
        return false;
    for (const Point2& p : inner.loop->points) {
        const int where = pointInLoop(p, outer.loop->points);
        if (where != -1)
            return where == 1;
    }
    return false;  // the same loop twice: neither contains the other
}

/// True when the facets clearly (≥ 2/3 of the length) orient the loop as a solid's boundary.
bool facetsSaySolid(const LoopInfo& info) {
    const double along = info.loop->along_facets_um;
    const double against = info.loop->against_facets_um;
    const double total = along + against;
    if (total <= 0 || 3 * std::max(along, against) < 2 * total)
        return false;
    return (along >= against ? info.area_um2 : -info.area_um2) > 0;
}

std::vector<LoopInfo> keptLoopsByArea(const std::vector<StitchedPath>& loops, double min_area_um2) {
    std::vector<LoopInfo> infos;
    for (const StitchedPath& loop : loops) {
        if (loop.points.size() < 3)
            continue;
        const double area = signedAreaUm2(loop.points);
        if (area == 0 || std::abs(area) <= min_area_um2)
            continue;
        infos.push_back({&loop, area, boundingBox(loop.points)});
    }
    std::stable_sort(infos.begin(), infos.end(), [](const LoopInfo& a, const LoopInfo& b) {
        return std::abs(a.area_um2) > std::abs(b.area_um2);
    });
    return infos;
}

/// is_hole[k] for loops sorted by decreasing |area| (see the header's rules).
std::vector<char> classifyHoles(const std::vector<LoopInfo>& infos) {
    std::vector<char> is_hole(infos.size(), 0);
    for (std::size_t k = 0; k < infos.size(); ++k) {
        for (std::size_t j = k; j-- > 0;) {
            if (!containsLoop(infos[j], infos[k]))
                continue;
            is_hole[k] = !is_hole[j] && !facetsSaySolid(infos[k]);
            break;
        }
    }
    return is_hole;
}

}  // namespace

Paths buildOutlines(const std::vector<StitchedPath>& loops, double min_area_um2) {
    const std::vector<LoopInfo> infos = keptLoopsByArea(loops, min_area_um2);
    if (infos.empty())
        return {};
    const std::vector<char> is_hole = classifyHoles(infos);
    Paths oriented;
    oriented.reserve(infos.size());
    for (std::size_t k = 0; k < infos.size(); ++k) {
        oriented.push_back(infos[k].loop->points);
        const bool counter_clockwise = infos[k].area_um2 > 0;
        if (counter_clockwise == static_cast<bool>(is_hole[k]))
            reverseLoop(oriented.back());
    }
    return clipAreas(oriented, {}, ClipOp::Union, FillRule::Positive);
}

Paths evenOddOutlines(const std::vector<StitchedPath>& loops, double min_area_um2) {
    Paths kept;
    for (const StitchedPath& loop : loops) {
        if (std::abs(signedAreaUm2(loop.points)) > std::max(min_area_um2, 0.0))
            kept.push_back(loop.points);
    }
    return clipAreas(kept, {}, ClipOp::Union, FillRule::EvenOdd);
}

}  // namespace mixengine
