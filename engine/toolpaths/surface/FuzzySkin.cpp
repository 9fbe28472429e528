#include "toolpaths/surface/FuzzySkin.h"

#include <cmath>
#include <random>

#include "geometry/Clip.h"

namespace mixengine {
namespace {

/// A uniform integer in [0, n) (n ≥ 1).
coord_um below(std::mt19937_64& random, coord_um n) {
    return n <= 1 ? 0 : static_cast<coord_um>(random() % static_cast<std::uint64_t>(n));
}

/// `v` scaled to length `length` (truncated to microns).
Point2 scaledTo(double x, double y, double length) {
    const double size = std::hypot(x, y);
    if (size <= 0)
        return {0, 0};
    return {static_cast<coord_um>(x * length / size), static_cast<coord_um>(y * length / size)};
}

bool isHole(const Path& loop) {
    return !counterClockwise(loop);
}

}  // namespace

FuzzySkinParams fuzzySkinParams(const Settings& s, int layer) {
    FuzzySkinParams p;
    p.enabled = s.boolean(key::magic_fuzzy_skin_enabled);
    if (p.enabled && layer == 0 && s.text(key::adhesion_type) == "brim")
        p.enabled = false;
    if (!p.enabled)
        return p;
    p.outside_only = s.boolean(key::magic_fuzzy_skin_outside_only);
    p.thickness_um = s.lengthMicrons(key::magic_fuzzy_skin_thickness);
    p.point_dist_um = s.lengthMicrons(key::magic_fuzzy_skin_point_dist);
    return p;
}

Path fuzzyLoop(const Path& loop, const FuzzySkinParams& params, std::uint64_t seed) {
    if (loop.size() < 2 || params.point_dist_um <= 0 || (params.outside_only && isHole(loop)))
        return loop;
    std::mt19937_64 random(seed);
    const coord_um min_dist = params.point_dist_um * 3 / 4;
    const coord_um spread = params.point_dist_um / 2;
    Path result;
    coord_um left_over = below(random, min_dist / 2);  // before the first new point
    Point2 from = loop.back();
    for (const Point2& to : loop) {
        const double dx = double(to.X - from.X), dy = double(to.Y - from.Y);
        const auto length = static_cast<coord_um>(std::hypot(dx, dy));
        coord_um along = left_over;
        if (along >= length)
            result.push_back({to.X - (to.X - from.X) / 2, to.Y - (to.Y - from.Y) / 2});
        for (; along < length; along += min_dist + below(random, spread)) {
            const coord_um sideways = below(random, 2 * params.thickness_um) - params.thickness_um;
            const Point2 ahead = scaledTo(dx, dy, double(along));
            const Point2 off = scaledTo(-dy, dx, double(sideways));
            result.push_back({from.X + ahead.X + off.X, from.Y + ahead.Y + off.Y});
        }
        left_over = along - length;
        from = to;
    }
    return result.size() >= 3 ? result : loop;
}

void applyFuzzySkin(std::vector<ExtrusionPath>& paths, const FuzzySkinParams& params, int layer) {
    if (!params.enabled)
        return;
    for (std::size_t i = 0; i < paths.size(); ++i) {
        ExtrusionPath& path = paths[i];
        if (path.feature != Feature::WallOuter || !path.closed)
            continue;
        const std::uint64_t seed = (std::uint64_t(std::uint32_t(layer)) << 32) ^ (i * 0x9E3779B97F4A7C15ULL);
        path.points = fuzzyLoop(path.points, params, seed);
    }
}

}  // namespace mixengine
