#include "geometry/PolygonOps.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "geometry/Clip.h"
#include "geometry/Point.h"
#include "geometry/SideBySide.h"

namespace mixengine {
namespace {

constexpr double kArcToleranceUm = 10.0;
constexpr coord_um kTouchingUm = 2;  // the reach of a boolean operation: loops that touch stay together

/// visit(a', b') for each side-by-side group a' of `a` and b' of `b` (SideBySide.h: loops farther
/// apart than `reach_um` do not meet in an operation of that reach), left to right; visit(a, b)
/// when they form one group.
template <typename Visit>
void forEachSide(const Paths& a, const Paths& b, coord_um reach_um, Visit visit) {
    const std::vector<std::vector<std::size_t>> groups = sideBySideGroups(a, b, reach_um);
    if (groups.empty()) {
        visit(a, b);
        return;
    }
    for (const std::vector<std::size_t>& group : groups) {
        Paths group_a, group_b;
        for (std::size_t k : group) {
            if (k < a.size())
                group_a.push_back(a[k]);
            else
                group_b.push_back(b[k - a.size()]);
        }
        visit(group_a, group_b);
    }
}

/// op(a, b) run on each side-by-side group apart (forEachSide), the results one after the other.
template <typename Op>
Paths bySide(const Paths& a, const Paths& b, coord_um reach_um, Op op) {
    Paths out;
    forEachSide(a, b, reach_um, [&](const Paths& group_a, const Paths& group_b) {
        Paths part = op(group_a, group_b);
        if (out.empty())
            out = std::move(part);
        else
            out.insert(out.end(), std::make_move_iterator(part.begin()), std::make_move_iterator(part.end()));
    });
    return out;
}

/// How far an offset by `delta_um` can move a vertex: the miter limit × delta (a margin added).
coord_um offsetReachUm(coord_um delta_um, double miter_limit) {
    return static_cast<coord_um>(std::ceil(std::max(miter_limit, 1.0) * double(std::abs(delta_um)))) + 10;
}

Paths offsetGroup(const Paths& polygons, coord_um delta_um, ClipperLib::JoinType join, double miter_limit) {
    if (polygons.empty())
        return {};
    ClipperLib::ClipperOffset offset(miter_limit, kArcToleranceUm);
    offset.AddPaths(polygons, join, ClipperLib::etClosedPolygon);
    Paths result;
    offset.Execute(result, static_cast<double>(delta_um));
    return result;
}

Paths offsetWith(const Paths& polygons, coord_um delta_um, ClipperLib::JoinType join,
                 double miter_limit = 2.0) {
    return bySide(polygons, {}, offsetReachUm(delta_um, miter_limit), [&](const Paths& group, const Paths&) {
        return offsetGroup(group, delta_um, join, miter_limit);
    });
}

Paths clipGroup(const Paths& a, const Paths& b, ClipperLib::ClipType operation) {
    if (operation == ClipperLib::ctIntersection && (a.empty() || b.empty()))
        return {};
    if (operation == ClipperLib::ctDifference && a.empty())
        return {};
    ClipperLib::Clipper clipper;
    clipper.AddPaths(a, ClipperLib::ptSubject, true);
    clipper.AddPaths(b, ClipperLib::ptClip, true);
    Paths result;
    clipper.Execute(operation, result, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    return result;
}

Paths clip(const Paths& a, const Paths& b, ClipperLib::ClipType operation) {
    return bySide(a, b, kTouchingUm, [&](const Paths& group_a, const Paths& group_b) {
        return clipGroup(group_a, group_b, operation);
    });
}

void collectIslands(const ClipperLib::PolyNode& node, std::vector<Paths>& islands) {
    for (const ClipperLib::PolyNode* child : node.Childs) {
        // Children of the root and of holes are outer contours.
        Paths island{child->Contour};
        for (const ClipperLib::PolyNode* hole : child->Childs) {
            island.push_back(hole->Contour);
            collectIslands(*hole, islands);
        }
        islands.push_back(std::move(island));
    }
}

__extension__ typedef __int128 Wide;

/// True when Clipper keeps every vertex of the closed `loop` (it drops repeated vertices and those
/// in line with their neighbours, spikes included); then `box` is set to the loop's bounds.
bool keptWhole(const Path& loop, Box2& box) {
    const std::size_t n = loop.size();
    if (n < 3)
        return false;
    box = {loop[0].X, loop[0].Y, loop[0].X, loop[0].Y};
    for (std::size_t i = 0; i < n; ++i) {
        const Point2& a = loop[(i + n - 1) % n];
        const Point2& p = loop[i];
        const Point2& b = loop[(i + 1) % n];
        const Wide cross = Wide(p.X - a.X) * Wide(b.Y - p.Y) - Wide(p.Y - a.Y) * Wide(b.X - p.X);
        if (p == b || cross == 0)
            return false;
        box = {std::min(box.left, p.X), std::min(box.top, p.Y), std::max(box.right, p.X),
               std::max(box.bottom, p.Y)};
    }
    return true;
}

}  // namespace

Paths offsetPolygons(const Paths& polygons, coord_um delta_um) {
    return offsetWith(polygons, delta_um, ClipperLib::jtRound);
}

Paths offsetMiter(const Paths& polygons, coord_um delta_um, Loops loops) {
    if (polygons.empty() || delta_um == 0)
        return polygons;
    constexpr double kMiterLimit = 1.2;
    return bySide(polygons, {}, offsetReachUm(delta_um, kMiterLimit), [&](const Paths& group, const Paths&) {
        return offsetGroup(loops == Loops::United ? group : clipGroup(group, {}, ClipperLib::ctUnion),
                           delta_um, ClipperLib::jtMiter, kMiterLimit);
    });
}

Paths offsetMiter(const Paths& polygons, coord_um delta_um, double miter_limit) {
    return offsetWith(polygons, delta_um, ClipperLib::jtMiter, miter_limit);
}

Paths offsetSquare(const Paths& polygons, coord_um delta_um) {
    if (polygons.empty() || delta_um == 0)
        return polygons;
    return offsetWith(polygons, delta_um, ClipperLib::jtSquare);
}

Paths openPolygons(const Paths& polygons, coord_um radius_um, Loops loops) {
    if (radius_um <= 0)
        return polygons;
    return offsetMiter(offsetMiter(polygons, -radius_um, loops), radius_um);
}

Paths unionOf(const Paths& polygons) {
    return clip(polygons, {}, ClipperLib::ctUnion);
}

Paths unionOf(const Paths& a, const Paths& b) {
    return clip(a, b, ClipperLib::ctUnion);
}

Paths unionOfUnited(const Paths& a, const Paths& b) {
    if (a.empty() || b.empty())
        return a.empty() ? b : a;
    return unionOf(a, b);
}

Paths intersectAll(const Paths& a, const Paths& b) {
    if (a.empty() || b.empty())
        return {};
    return clip(a, b, ClipperLib::ctIntersection);
}

Paths differenceOf(const Paths& a, const Paths& b) {
    if (a.empty())
        return {};
    return clip(a, b, ClipperLib::ctDifference);
}

Paths cleanPolygons(const Paths& polygons, coord_um tolerance_um) {
    Paths result;
    ClipperLib::CleanPolygons(polygons, result, static_cast<double>(tolerance_um));
    std::erase_if(result, [](const Path& p) { return p.size() < 3; });
    return result;
}

Paths clipLines(const Paths& lines, const Paths& area) {
    if (lines.empty() || area.empty())
        return {};
    ClipperLib::Clipper clipper;
    clipper.AddPaths(lines, ClipperLib::ptSubject, false);
    clipper.AddPaths(area, ClipperLib::ptClip, true);
    ClipperLib::PolyTree tree;
    clipper.Execute(ClipperLib::ctIntersection, tree, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    Paths pieces;
    ClipperLib::OpenPathsFromPolyTree(tree, pieces);
    return pieces;
}

double areaUm2(const Paths& polygons) {
    double total = 0;
    for (const Path& p : polygons)
        total += ClipperLib::Area(p);
    return total;
}

namespace {

/// The islands of a op b, side-by-side groups apart (forEachSide).
std::vector<Paths> islandsOf(const Paths& a, const Paths& b, ClipperLib::ClipType operation) {
    std::vector<Paths> islands;
    forEachSide(a, b, kTouchingUm, [&](const Paths& group_a, const Paths& group_b) {
        ClipperLib::Clipper clipper;
        clipper.AddPaths(group_a, ClipperLib::ptSubject, true);
        clipper.AddPaths(group_b, ClipperLib::ptClip, true);
        ClipperLib::PolyTree tree;
        clipper.Execute(operation, tree, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
        collectIslands(tree, islands);
    });
    return islands;
}

Paths withoutSmallIslands(std::vector<Paths> islands, double min_area_um2) {
    Paths kept;
    for (Paths& island : islands) {
        if (areaUm2(island) < min_area_um2)
            continue;
        for (Path& p : island)
            kept.push_back(std::move(p));
    }
    return kept;
}

}  // namespace

std::vector<Paths> splitIslands(const Paths& polygons) {
    return islandsOf(polygons, {}, ClipperLib::ctUnion);
}

Paths removeSmallIslands(const Paths& polygons, double min_area_um2) {
    if (min_area_um2 <= 0)
        return polygons;
    return withoutSmallIslands(splitIslands(polygons), min_area_um2);
}

Paths removeSmallOutlines(const Paths& polygons, double min_area_um2) {
    std::vector<bool> dropped(polygons.size(), false);
    std::vector<std::size_t> small_holes;
    bool any = false;
    for (std::size_t k = 0; k < polygons.size(); ++k) {
        const double area = signedAreaUm2(polygons[k]);
        if (std::abs(area) >= min_area_um2)
            continue;
        if (area >= 0)
            dropped[k] = any = true;
        else
            small_holes.push_back(k);
    }
    if (!any)
        return polygons;
    for (std::size_t hole : small_holes) {
        for (std::size_t k = 0; k < polygons.size() && !polygons[hole].empty(); ++k) {
            if (dropped[k] && k != hole && pointInLoop(polygons[hole][0], polygons[k]) != 0) {
                dropped[hole] = true;
                break;
            }
        }
    }
    Paths kept;
    for (std::size_t k = 0; k < polygons.size(); ++k) {
        if (!dropped[k])
            kept.push_back(polygons[k]);
    }
    return kept;
}

Paths differenceWithoutSmallIslands(const Paths& a, const Paths& b, double min_area_um2) {
    if (min_area_um2 <= 0)
        return differenceOf(a, b);
    if (a.empty())
        return {};
    return withoutSmallIslands(islandsOf(a, b, ClipperLib::ctDifference), min_area_um2);
}

Box2 boundsOf(const Paths& polygons) {
    bool any = false;
    Box2 box{0, 0, 0, 0};
    for (const Path& loop : polygons) {
        Box2 b{0, 0, 0, 0};
        if (!keptWhole(loop, b)) {
            ClipperLib::Clipper clipper;
            if (!clipper.AddPath(loop, ClipperLib::ptSubject, true))
                continue;
            b = clipper.GetBounds();
        }
        box = any ? Box2{std::min(box.left, b.left), std::min(box.top, b.top), std::max(box.right, b.right),
                         std::max(box.bottom, b.bottom)}
                  : b;
        any = true;
    }
    return box;
}

double lengthUm(const Path& path, bool closed) {
    double total = 0;
    for (std::size_t i = 1; i < path.size(); ++i)
        total += distanceUm(path[i], path[i - 1]);
    if (closed && path.size() > 2)
        total += distanceUm(path.front(), path.back());
    return total;
}

}  // namespace mixengine
