#include "toolpaths/walls/Seam.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>

#include "common/Error.h"
#include "geometry/Clip.h"

namespace mixengine {
namespace {

SeamType seamTypeOf(const std::string& text) {
    if (text == "back")
        return SeamType::Back;
    if (text == "shortest")
        return SeamType::Shortest;
    if (text == "random")
        return SeamType::Random;
    if (text == "sharpest_corner")
        return SeamType::SharpestCorner;
    throw InputError("setting 'z_seam_type': unknown value '" + text + "'");
}

SeamCorner seamCornerOf(const std::string& text) {
    if (text == "z_seam_corner_none")
        return SeamCorner::None;
    if (text == "z_seam_corner_inner")
        return SeamCorner::Inner;
    if (text == "z_seam_corner_outer")
        return SeamCorner::Outer;
    if (text == "z_seam_corner_any")
        return SeamCorner::Any;
    if (text == "z_seam_corner_weighted")
        return SeamCorner::Weighted;
    throw InputError("setting 'z_seam_corner': unknown value '" + text + "'");
}

std::uint64_t mix(std::uint64_t x) {  // splitmix64 finaliser
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}

/// The squared distance in µm² as CuraEngine 4.13 takes it: 64-bit, wrapping far outside the plate.
std::int64_t squaredUm2(const Point2& a, const Point2& b) {
    const auto dx = static_cast<std::uint64_t>(a.X - b.X);
    const auto dy = static_cast<std::uint64_t>(a.Y - b.Y);
    return static_cast<std::int64_t>(dx * dx + dy * dy);
}

/// The angle on the material's side (the left) of the corner a-b-c in radians, 0 … 2π, in
/// single precision as CuraEngine 4.13 measures it: from the exact determinant and dot product of
/// the two legs; a corner with collinear legs is 0 when they point the same way, else π.
float leftAngleRad(const Point2& a, const Point2& b, const Point2& c) {
    const coord_um ax = a.X - b.X, ay = a.Y - b.Y;
    const coord_um cx = c.X - b.X, cy = c.Y - b.Y;
    const coord_um det = ax * cy - ay * cx;
    if (det == 0) {
        const bool same_way = ax != 0 ? (ax > 0) == (cx > 0) : (ay > 0) == (cy > 0);
        return same_way ? 0.0F : static_cast<float>(std::numbers::pi);
    }
    const float angle = static_cast<float>(-std::atan2(double(det), double(ax * cx + ay * cy)));
    return angle >= 0 ? angle : static_cast<float>(2 * std::numbers::pi + double(angle));
}

/// One search for a loop's seam vertex as CuraEngine 4.13's path order optimiser makes it.
struct SeamSearch {
    Point2 focus;              ///< the search starts at the vertex nearest to it
    Point2 target;             ///< vertices are scored by their squared distance to it …
    bool fixed_score = false;  ///< … or all alike (10 mm, sharpest corner)
    bool fixed_shift = false;  ///< a corner lessens the score by up to 100 mm² (shortest)
    SeamCorner corner = SeamCorner::None;
};

/// The score of `loop`'s vertex i (lower is better), in single precision as CuraEngine 4.13: the
/// squared distance (or 10 mm) lessened by the corner shift (a tenth of the score, or 100 mm²)
/// times how far the corner's angle ratio (leftAngleRad / π, 0 … 2, above 1 concave) bends the
/// preferred way — concave bends twice for "weighted".
float seamScore(const Path& loop, std::size_t i, const SeamSearch& search) {
    const std::size_t n = loop.size();
    const Point2& p = loop[i];
    float score = search.fixed_score ? 10'000.0F : static_cast<float>(squaredUm2(p, search.target));
    const float ratio = static_cast<float>(double(leftAngleRad(loop[(i + n - 1) % n], p, loop[(i + 1) % n])) /
                                           std::numbers::pi);
    const float shift = search.fixed_shift ? 1e8F : score / 10;
    switch (search.corner) {
        case SeamCorner::Inner:
            if (ratio > 1)
                score -= (ratio - 1) * shift;
            break;
        case SeamCorner::Outer:
            if (ratio < 1)
                score -= (1 - ratio) * shift;
            break;
        case SeamCorner::Any:  // CuraEngine takes this bend in double precision
            score = static_cast<float>(double(score) - std::fabs(double(ratio - 1)) * double(shift));
            break;
        case SeamCorner::Weighted: {
            float pull = static_cast<float>(std::fabs(double(ratio - 1)) * double(shift));
            if (ratio > 1)
                pull *= 2;
            score -= pull;
            break;
        }
        case SeamCorner::None:
            break;
    }
    return score;
}

/// The seam vertex as CuraEngine 4.13 finds it: starting at the vertex nearest to the focus (the
/// first in the loop's order on an exact tie) and going round once in the loop's order, a vertex
/// replaces the best so far when its score less 25 µm² is below the best score — so of vertices
/// scoring within 25 µm² the last one met wins, while where the scores are too large for single
/// precision to hold 25 µm² only a strictly lower score wins.
std::size_t searchSeam(const Path& loop, const SeamSearch& search) {
    constexpr float kEpsilonUm2 = 25.0F;
    const std::size_t n = loop.size();
    std::size_t start = 0;
    std::int64_t nearest = std::numeric_limits<std::int64_t>::max();
    for (std::size_t i = 0; i < n; ++i) {
        const std::int64_t d2 = squaredUm2(search.focus, loop[i]);
        if (d2 < nearest)
            nearest = d2, start = i;
    }
    std::size_t chosen = start;
    float best = std::numeric_limits<float>::infinity();
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t i = (start + k) % n;
        const float score = seamScore(loop, i, search);
        if (score - kEpsilonUm2 < best)
            chosen = i, best = score;
    }
    return chosen;
}

/// Far behind the plate, a little to the left of every vertex: CuraEngine 4.13's focus when the seam
/// is not at a user-specified point (the square root keeps squared distances within 64 bits).
const Point2 kFarBackUm{0, 3'037'000'499};

/// An outer wall's seam, and whether the wall runs counter-clockwise (a part's outline, else a hole's).
struct OuterSeam {
    Point2 at;
    bool counter_clockwise = true;
};

/// The seam of the outer wall an inner wall belongs to: of the outer walls running the same way (a
/// part's or a hole's), the one whose seam is nearest to a vertex of the inner wall; none without one.
std::optional<Point2> ownOuterSeam(const Path& inner, const std::vector<OuterSeam>& outer_seams) {
    const bool ccw = counterClockwise(inner);
    std::optional<Point2> own;
    std::int64_t nearest = std::numeric_limits<std::int64_t>::max();
    for (const OuterSeam& seam : outer_seams) {
        if (seam.counter_clockwise != ccw)
            continue;
        for (const Point2& p : inner) {
            const std::int64_t d2 = squaredUm2(p, seam.at);
            if (d2 < nearest)
                nearest = d2, own = seam.at;
        }
    }
    return own;
}

/// Rotates a loop so that vertex `start` comes first, and fixes its start there.
void startAt(ExtrusionPath& path, std::size_t start) {
    std::rotate(path.points.begin(), path.points.begin() + static_cast<std::ptrdiff_t>(start),
                path.points.end());
    path.fixed_start = true;
}

}  // namespace

SeamParams seamParamsFrom(const Settings& s, const Point2& mesh_centre_um) {
    SeamParams p;
    p.type = seamTypeOf(s.text(key::z_seam_type));
    p.corner = seamCornerOf(s.text(key::z_seam_corner));
    p.position_um = {s.lengthMicrons(key::z_seam_x), s.lengthMicrons(key::z_seam_y)};
    if (s.boolean(key::z_seam_relative)) {
        p.position_um.X += mesh_centre_um.X;
        p.position_um.Y += mesh_centre_um.Y;
    }
    return p;
}

std::size_t seamVertex(const Path& loop, const SeamParams& params, std::uint64_t seed) {
    if (loop.empty())
        return 0;
    switch (params.type) {
        case SeamType::Back:
            return searchSeam(loop, {params.position_um, params.position_um, false, false, params.corner});
        case SeamType::Random:
            return static_cast<std::size_t>(mix(seed) % loop.size());
        case SeamType::SharpestCorner:
            if (params.corner == SeamCorner::None)
                break;
            return searchSeam(loop, {kFarBackUm, kFarBackUm, true, false, params.corner});
        case SeamType::Shortest:
            break;
    }
    return 0;
}

void placeSeams(std::vector<ExtrusionPath>& paths, const SeamParams& params, int layer) {
    if (params.type == SeamType::Shortest ||
        (params.type == SeamType::SharpestCorner && params.corner == SeamCorner::None))
        return;  // CuraEngine 4.13 starts these where the head is
    std::vector<OuterSeam> outer_seams;
    for (std::size_t i = 0; i < paths.size(); ++i) {
        ExtrusionPath& path = paths[i];
        if (!path.closed || path.points.empty() || path.feature == Feature::WallInner)
            continue;
        const std::uint64_t seed = mix(static_cast<std::uint64_t>(layer)) ^ mix(i + 0x51ed27ULL);
        startAt(path, seamVertex(path.points, params, seed));
        if (path.feature == Feature::WallOuter)
            outer_seams.push_back({path.points.front(), counterClockwise(path.points)});
    }
    for (std::size_t i = 0; i < paths.size(); ++i) {
        ExtrusionPath& path = paths[i];
        if (!path.closed || path.points.empty() || path.feature != Feature::WallInner)
            continue;
        const std::optional<Point2> outer = ownOuterSeam(path.points, outer_seams);
        const std::uint64_t seed = mix(static_cast<std::uint64_t>(layer)) ^ mix(i + 0x51ed27ULL);
        startAt(path, outer ? searchSeam(path.points, {kFarBackUm, *outer, false, false, SeamCorner::None})
                            : seamVertex(path.points, params, seed));
    }
}

}  // namespace mixengine
