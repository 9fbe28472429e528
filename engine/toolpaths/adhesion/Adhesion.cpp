#include "toolpaths/adhesion/Adhesion.h"

#include <algorithm>
#include <cmath>

#include "geometry/Clip.h"
#include "geometry/PolygonOps.h"
#include "slicing/OutlineCleanup.h"
#include "toolpaths/adhesion/DraftShield.h"
#include "toolpaths/core/FeatureStyle.h"
#include "toolpaths/support/Support.h"

namespace mixengine {
namespace {

long long cross(const Point2& o, const Point2& a, const Point2& b) {
    return (a.X - o.X) * (b.Y - o.Y) - (a.Y - o.Y) * (b.X - o.X);
}

/// Without the holes that hold no other loop of `area` (CuraEngine's removeEmptyHoles).
Paths withoutEmptyHoles(const Paths& area) {
    Paths kept;
    for (const Path& loop : area) {
        const bool hole = !counterClockwise(loop);
        const bool holds_something =
            hole && std::any_of(area.begin(), area.end(), [&](const Path& other) {
                return counterClockwise(other) && !other.empty() && pointInLoop(other.front(), loop) != 0;
            });
        if (!hole || holds_something)
            kept.push_back(loop);
    }
    return kept;
}

/// The islands of `models` that get a wall: as CuraEngine 4.13 drops a layer part too thin for its outer
/// wall (wall_line_width_0 × initial_layer_line_width_factor on layer 0) before the brim is made — unless
/// it fills outline gaps (fill_outline_gaps keeps such parts, the whole part a gap).
Paths partsWithWalls(const Paths& models, const Settings& s) {
    if (s.integer(key::wall_line_count) <= 0 || s.boolean(key::fill_outline_gaps))
        return models;
    const coord_um half_wall =
        static_cast<coord_um>(std::llround(double(s.lengthMicrons(key::wall_line_width_0)) *
                                           s.ratio(key::initial_layer_line_width_factor))) /
        2;
    Paths kept;
    for (const Paths& island : splitIslands(models)) {
        if (!offsetMiter(island, -half_wall, Loops::United).empty())
            kept.insert(kept.end(), island.begin(), island.end());
    }
    return kept;
}

/// What the brim goes around, as CuraEngine 4.13 takes it: the outlines grown by brim_gap (mitred),
/// united, closed by 20 µm (neighbours that nearly touch become one), simplified (200 µm segments,
/// 50 µm deviation); with brim_outside_only, without the holes that hold nothing.
Paths brimBase(const Paths& models, coord_um gap_um, bool outside_only) {
    constexpr coord_um kJoinUm = 20;
    Paths base = gap_um != 0 ? offsetMiter(models, gap_um) : unionOf(models);
    base = offsetMiter(offsetMiter(base, kJoinUm, Loops::United), -kJoinUm, Loops::United);
    for (Path& loop : base)
        loop = simplifyLoop(loop, 200, 50);
    std::erase_if(base, [](const Path& loop) { return loop.size() < 3; });
    return outside_only ? withoutEmptyHoles(base) : base;
}

/// What the skirt goes around, as CuraEngine 4.13 takes it: the approximate convex hull
/// (DraftShield.h) of the models' outlines and of the other things on the layer (their points' convex
/// hull here), closed by 20 µm and simplified (200 µm segments, 50 µm deviation) — the vertices that
/// leaves along the hull's sides are what meshfix_maximum_resolution later removes or keeps.
Paths skirtBase(const Paths& models, const Paths& extras) {
    constexpr coord_um kJoinUm = 20;
    Paths around = models;
    if (!extras.empty())
        around.push_back(convexHull(extras));
    Paths base = approxConvexHull(around, 0);
    base = offsetMiter(offsetMiter(base, kJoinUm, Loops::United), -kJoinUm, Loops::United);
    for (Path& loop : base)
        loop = simplifyLoop(loop, 200, 50);
    std::erase_if(base, [](const Path& loop) { return loop.size() < 3; });
    return base;
}

/// Loops around `base`: the first `first_um` outside it, then one width further out each; at
/// least `count` and more until `min_length_um` is reached. Outermost first. As CuraEngine, a loop's
/// holes smaller than 100 line widths squared are left out.
std::vector<ExtrusionPath> rings(const Paths& base, coord_um first_um, int count, double min_length_um,
                                 const FeatureStyle& style) {
    std::vector<ExtrusionPath> loops;
    double total = 0;
    const double min_hole_um2 = 100.0 * double(style.width_um) * double(style.width_um);
    constexpr int kMaxExtra = 1000;  // a safety bound on the lines added for the minimal length
    for (int i = 0; i < count || (total < min_length_um && i < count + kMaxExtra); ++i) {
        Paths ring = offsetPolygons(base, first_um + coord_um(i) * style.width_um);
        if (ring.empty())
            break;
        std::erase_if(ring, [&](const Path& p) {
            const double area = signedAreaUm2(p);
            return area < 0 && area > -min_hole_um2;
        });
        for (const Path& p : ring) {
            ExtrusionPath path;
            path.points = p;
            path.closed = true;
            path.width_um = style.width_um;
            path.feature = Feature::Skirt;
            path.speed_mm_s = style.speed_mm_s;
            path.flow = style.flow;
            path.extruder = style.extruder;
            total += lengthUm(p, true);
            loops.push_back(std::move(path));
        }
    }
    std::reverse(loops.begin(), loops.end());
    return loops;
}

/// The brim in the shields' foot (see the header): loops inward from the shields' outline.
std::vector<ExtrusionPath> shieldBrim(const Paths& shields, const Paths& brim_base, coord_um brim_reach_um,
                                      int count, const FeatureStyle& style) {
    const coord_um w = style.width_um;
    const coord_um depth = coord_um(count + count % 2) * w;
    Paths foot = differenceOf(shields, offsetPolygons(shields, -depth - w));
    foot = differenceOf(foot, offsetPolygons(brim_base, brim_reach_um + w));
    std::vector<ExtrusionPath> loops;
    constexpr int kMaxLoops = 1000;
    for (int i = 0; i < kMaxLoops && !foot.empty(); ++i) {
        for (const Path& p : foot)
            loops.push_back(styledPath(p, true, Feature::Skirt, style));
        foot = offsetPolygons(foot, -w);
    }
    return loops;
}

}  // namespace

Path convexHull(const Paths& polygons) {
    std::vector<Point2> pts;
    for (const Path& p : polygons)
        pts.insert(pts.end(), p.begin(), p.end());
    std::sort(pts.begin(), pts.end(),
              [](const Point2& a, const Point2& b) { return a.X != b.X ? a.X < b.X : a.Y < b.Y; });
    pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
    if (pts.size() < 3)
        return pts;
    Path hull(2 * pts.size());
    std::size_t k = 0;
    for (const Point2& p : pts) {  // lower hull
        while (k >= 2 && cross(hull[k - 2], hull[k - 1], p) <= 0)
            --k;
        hull[k++] = p;
    }
    for (std::size_t i = pts.size() - 1, lower = k + 1; i-- > 0;) {  // upper hull
        while (k >= lower && cross(hull[k - 2], hull[k - 1], pts[i]) <= 0)
            --k;
        hull[k++] = pts[i];
    }
    hull.resize(k - 1);
    return hull;
}

void simplifyAdhesion(const Settings& global, const std::vector<Settings>* extruders,
                      std::vector<ExtrusionPath>& paths) {
    const int nr = global.extruderIndex(key::adhesion_extruder_nr);
    const Settings& s = trainSettings(global, extruders, nr < 0 ? 0 : nr);
    const coord_um resolution = s.lengthMicrons(key::meshfix_maximum_resolution);
    const coord_um deviation = s.lengthMicrons(key::meshfix_maximum_deviation);
    for (ExtrusionPath& path : paths) {
        if (path.closed && path.flows.empty())
            path.points = simplifyLoop(path.points, resolution, deviation);
    }
    std::erase_if(paths, [](const ExtrusionPath& path) { return path.closed && path.points.size() < 3; });
}

AdhesionResult generateAdhesion(const AdhesionInput& in) {
    AdhesionResult result;
    const Settings& g = *in.global;
    const std::string type = g.text(key::adhesion_type);
    if (type == "none" || type == "raft" || in.models.empty())
        return result;
    int nr = g.extruderIndex(key::adhesion_extruder_nr);
    nr = nr < 0 ? 0 : nr;
    const Settings& s = trainSettings(g, in.extruders, nr);
    FeatureStyle style = featureStyle(s,
                                      {key::skirt_brim_line_width, key::skirt_brim_speed,
                                       key::skirt_brim_material_flow, key::adhesion_extruder_nr},
                                      0);
    style.speed_mm_s =
        s.velocityMmPerS(key::skirt_brim_speed);  // CuraEngine does not slow skirt and brim down
    style.extruder = nr;
    const double min_length = s.millimetres(key::skirt_brim_minimal_length) * 1000;
    if (type == "brim") {
        const coord_um gap = s.lengthMicrons(key::brim_gap);
        const Paths base = brimBase(partsWithWalls(in.models, s), gap, s.boolean(key::brim_outside_only));
        const int count = static_cast<int>(std::max<long long>(0, s.integer(key::brim_line_count)));
        result.paths = rings(base, style.width_um / 2, count, min_length, style);
        if (!in.shields.empty()) {
            const coord_um reach = style.width_um / 2 + coord_um(std::max(0, count - 1)) * style.width_um;
            const std::vector<ExtrusionPath> foot = shieldBrim(in.shields, base, reach, count, style);
            result.paths.insert(result.paths.end(), foot.begin(), foot.end());
        }
        return result;
    }
    if (type != "skirt")
        result.warnings.push_back("adhesion_type '" + type + "' is not supported; printing a skirt instead");
    Paths hull = skirtBase(in.models, in.extras);
    coord_um first = s.lengthMicrons(key::skirt_gap) + style.width_um / 2;
    if (!in.shields.empty()) {  // around the shields too, as CuraEngine
        hull = approxConvexHull(unionOf(offsetPolygons(hull, first - style.width_um), in.shields), 0);
        first = style.width_um;
    }
    const int count = static_cast<int>(std::max<long long>(0, s.integer(key::skirt_line_count)));
    result.paths = rings(hull, first, count, min_length, style);
    return result;
}

}  // namespace mixengine
