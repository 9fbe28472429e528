#include "toolpaths/adhesion/Adhesion.h"

#include <algorithm>

#include "geometry/Clip.h"
#include "geometry/PolygonOps.h"
#include "toolpaths/adhesion/DraftShield.h"
#include "toolpaths/core/FeatureStyle.h"
#include "toolpaths/support/Support.h"

namespace mixengine {
namespace {

long long cross(const Point2& o, const Point2& a, const Point2& b) {
    return (a.X - o.X) * (b.Y - o.Y) - (a.Y - o.Y) * (b.X - o.X);
}

Paths outerContours(const Paths& polygons) {
    Paths outer;
    for (const Path& p : unionOf(polygons)) {
        if (counterClockwise(p))
            outer.push_back(p);
    }
    return outer;
}

/// Loops around `base`: the first `first_um` outside it, then one width further out each; at
/// least `count` and more until `min_length_um` is reached. Outermost first.
std::vector<ExtrusionPath> rings(const Paths& base, coord_um first_um, int count, double min_length_um,
                                 const FeatureStyle& style) {
    std::vector<ExtrusionPath> loops;
    double total = 0;
    constexpr int kMaxExtra = 1000;  // a safety bound on the lines added for the minimal length
    for (int i = 0; i < count || (total < min_length_um && i < count + kMaxExtra); ++i) {
        const Paths ring = offsetPolygons(base, first_um + coord_um(i) * style.width_um);
        if (ring.empty())
            break;
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
        const bool outside_only = s.boolean(key::brim_outside_only);
        const Paths base = outside_only ? outerContours(in.models) : unionOf(in.models);
        const coord_um gap = s.lengthMicrons(key::brim_gap);
        const int count = static_cast<int>(std::max<long long>(0, s.integer(key::brim_line_count)));
        result.paths = rings(base, gap + style.width_um / 2, count, min_length, style);
        if (!in.shields.empty()) {
            const coord_um reach =
                gap + style.width_um / 2 + coord_um(std::max(0, count - 1)) * style.width_um;
            const std::vector<ExtrusionPath> foot = shieldBrim(in.shields, base, reach, count, style);
            result.paths.insert(result.paths.end(), foot.begin(), foot.end());
        }
        return result;
    }
    if (type != "skirt")
        result.warnings.push_back("adhesion_type '" + type + "' is not supported; printing a skirt instead");
    Paths everything = in.models;
    everything.insert(everything.end(), in.extras.begin(), in.extras.end());
    Paths hull{convexHull(everything)};
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
