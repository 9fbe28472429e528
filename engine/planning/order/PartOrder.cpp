#include "planning/order/PartOrder.h"

#include <cmath>
#include <limits>

#include "geometry/PointQueries.h"
#include "geometry/PolygonOps.h"

namespace mixengine {
namespace {

constexpr std::size_t kNoPart = std::numeric_limits<std::size_t>::max();

bool inBox(const Box2& box, const Point2& p) {
    return p.X >= box.left && p.X <= box.right && p.Y >= box.top && p.Y <= box.bottom;
}

/// Finds the part of a point; tries the part found last first (paths of a part mostly come together).
struct PartLocator {
    const std::vector<Paths>& parts;
    std::vector<Box2> boxes;
    std::size_t last = 0;

    explicit PartLocator(const std::vector<Paths>& p) : parts(p) {
        for (const Paths& part : parts)
            boxes.push_back(boundsOf(part));
    }
    bool holds(std::size_t i, const Point2& p) const {
        return inBox(boxes[i], p) && insideArea(parts[i], p, true);
    }
    std::size_t partOf(const Point2& p) {
        if (last < parts.size() && holds(last, p))
            return last;
        for (std::size_t i = 0; i < parts.size(); ++i) {
            if (i != last && holds(i, p))
                return last = i;
        }
        return kNoPart;
    }
    std::size_t partOf(const ExtrusionPath& path) {
        for (const Point2& p : path.points) {
            const std::size_t part = partOf(p);
            if (part != kNoPart)
                return part;
        }
        return kNoPart;
    }
};

using GroupField = std::vector<ExtrusionPath> MeshLayerGroups::*;

void distribute(const MeshLayerGroups& groups, GroupField field, PartLocator& locator, LayerParts& out) {
    for (const ExtrusionPath& path : groups.*field) {
        const std::size_t part = out.parts.size() == 1 ? 0 : locator.partOf(path);
        ((part == kNoPart ? out.rest : out.parts[part]).*field).push_back(path);
    }
}

/// The part's outer wall loop with the largest area, else its outline's outer contour.
void pickLoop(const MeshLayerGroups& part, const Paths& outline, Path& loop,
              std::optional<std::size_t>& fixed) {
    double best = -1;
    for (const ExtrusionPath& wall : part.outer_walls) {
        if (!wall.closed || wall.points.size() < 3)
            continue;
        const double area = std::abs(areaUm2(Paths{wall.points}));
        if (area > best) {
            best = area;
            loop = wall.points;
            fixed = wall.fixed_start ? std::optional<std::size_t>(0) : std::nullopt;
        }
    }
    if (best < 0 && !outline.empty())
        loop = outline.front();
}

/// Squared distance in single precision, as CuraEngine's part order compares them (vSize2f).
float distance2f(const Point2& a, const Point2& b) {
    const float dx = static_cast<float>(a.X - b.X), dy = static_cast<float>(a.Y - b.Y);
    return dx * dx + dy * dy;
}

std::size_t nearestVertex(const Path& loop, const Point2& to) {
    std::size_t best = 0;
    double best_distance = std::numeric_limits<double>::max();
    for (std::size_t i = 0; i < loop.size(); ++i) {
        const double d = distance2(loop[i], to);
        if (d < best_distance)
            best = i, best_distance = d;
    }
    return best;
}

}  // namespace

LayerParts splitByPart(const MeshLayerGroups& groups) {
    LayerParts out;
    out.parts.resize(groups.parts.size());
    out.rest.comb_area = groups.comb_area;
    out.rest.infill_start = groups.infill_start;
    out.rest.ironing = groups.ironing;
    PartLocator locator(groups.parts);
    for (GroupField field : {&MeshLayerGroups::inner_walls, &MeshLayerGroups::outer_walls,
                             &MeshLayerGroups::skin, &MeshLayerGroups::infill})
        distribute(groups, field, locator, out);
    out.loops.resize(out.parts.size());
    out.fixed_starts.resize(out.parts.size());
    for (std::size_t i = 0; i < out.parts.size(); ++i) {
        out.parts[i].infill_start = groups.infill_start;
        pickLoop(out.parts[i], groups.parts[i], out.loops[i], out.fixed_starts[i]);
    }
    return out;
}

std::vector<std::size_t> seamPartOrder(const LayerParts& parts, const std::optional<Point2>& seam_position,
                                       const Point2& head) {
    const Point2 from = seam_position ? *seam_position : head;
    std::vector<Point2> starts;
    for (std::size_t i = 0; i < parts.loops.size(); ++i) {
        const Path& loop = parts.loops[i];
        starts.push_back(
            loop.empty() ? from
                         : loop[parts.fixed_starts[i] ? *parts.fixed_starts[i] : nearestVertex(loop, from)]);
    }
    std::vector<std::size_t> order;
    std::vector<bool> picked(starts.size(), false);
    Point2 at = from;
    while (order.size() < starts.size()) {
        std::size_t best = 0;
        float best_distance = std::numeric_limits<float>::infinity();
        for (std::size_t i = 0; i < starts.size(); ++i) {
            const float d = distance2f(starts[i], at);
            if (!picked[i] && d < best_distance)
                best = i, best_distance = d;
        }
        picked[best] = true;
        order.push_back(best);
        at = starts[best];
    }
    return order;
}

std::size_t nearestPart(const LayerParts& parts, const std::vector<bool>& done, const Point2& head) {
    std::size_t best = parts.parts.size();
    double best_distance = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < parts.loops.size(); ++i) {
        if (done[i])
            continue;
        const Path& loop = parts.loops[i];
        const double d = loop.empty() ? std::numeric_limits<double>::max()
                                      : distance2(loop[nearestVertex(loop, head)], head);
        if (best == parts.parts.size() || d < best_distance)
            best = i, best_distance = d;
    }
    return best;
}

}  // namespace mixengine
