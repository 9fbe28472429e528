#include "planning/order/SkinOrder.h"

#include <limits>
#include <map>

#include "geometry/PointQueries.h"

namespace mixengine {
namespace {

/// One skin part: its paths by stage, and the points it is found by.
struct SkinPart {
    std::map<std::uint8_t, std::vector<ExtrusionPath>> stages;
    Path loop_points;
    Path all_points;
};

const Path& representation(const SkinPart& part) {
    return part.loop_points.empty() ? part.all_points : part.loop_points;
}

/// Of the point sets `points(i)` (i < count) not `done`, the one with the vertex nearest to `from` (the
/// first of equals; `count` when none is left), and that vertex.
template <typename Points>
std::size_t nearestUndone(std::size_t count, Points points, const std::vector<bool>& done, const Point2& from,
                          Point2& vertex) {
    std::size_t best = count;
    double best_distance = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < count; ++i) {
        if (done[i])
            continue;
        for (const Point2& p : points(i)) {
            const double d = distance2(p, from);
            if (d < best_distance)
                best_distance = d, best = i, vertex = p;
        }
    }
    return best;
}

void collect(ExtrusionPath path, std::map<std::uint32_t, std::size_t>& index, std::vector<SkinPart>& parts) {
    const auto [it, added] = index.try_emplace(path.skin_part, parts.size());
    if (added)
        parts.emplace_back();
    SkinPart& part = parts[it->second];
    Path& points = path.skin_stage == 1 ? part.loop_points : part.all_points;
    points.insert(points.end(), path.points.begin(), path.points.end());
    part.stages[path.skin_stage].push_back(std::move(path));
}

}  // namespace

std::vector<ExtrusionPath> loopsNearestFirst(std::vector<ExtrusionPath> loops, const Point2& from) {
    std::vector<ExtrusionPath> ordered;
    std::vector<bool> done(loops.size(), false);
    Point2 at = from;
    for (std::size_t n = 0; n < loops.size(); ++n) {
        Point2 vertex = at;
        const std::size_t best = nearestUndone(
            loops.size(), [&](std::size_t i) -> const Path& { return loops[i].points; }, done, at, vertex);
        done[best] = true;
        at = vertex;
        ordered.push_back(std::move(loops[best]));
    }
    return ordered;
}

std::vector<std::vector<ExtrusionPath>> skinPrintGroups(std::vector<ExtrusionPath> paths,
                                                        const Point2& from) {
    std::vector<ExtrusionPath> before, after;
    std::vector<SkinPart> parts;
    std::map<std::uint32_t, std::size_t> index;
    for (ExtrusionPath& path : paths) {
        if (path.skin_part != 0)
            collect(std::move(path), index, parts);
        else
            (parts.empty() ? before : after).push_back(std::move(path));
    }
    std::vector<std::vector<ExtrusionPath>> groups;
    if (!before.empty())
        groups.push_back(std::move(before));
    std::vector<bool> done(parts.size(), false);
    Point2 at = from;
    for (;;) {
        Point2 vertex = at;
        const std::size_t next = nearestUndone(
            parts.size(), [&](std::size_t i) -> const Path& { return representation(parts[i]); }, done, at,
            vertex);
        if (next == parts.size())
            break;
        done[next] = true;
        at = vertex;
        for (auto& [stage, stage_paths] : parts[next].stages)
            groups.push_back(std::move(stage_paths));
    }
    if (!after.empty())
        groups.push_back(std::move(after));
    return groups;
}

}  // namespace mixengine
