#include "toolpaths/walls/Seam.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

#include "common/Error.h"

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

/// The point reached by walking from vertex i along the loop (step +1 or -1) for at least `reach`.
const Point2& walk(const Path& loop, std::size_t i, int step, double reach) {
    const std::size_t n = loop.size();
    std::size_t j = i;
    double travelled = 0;
    for (std::size_t k = 1; k < n && travelled < reach; ++k) {
        const std::size_t next = step > 0 ? (j + 1) % n : (j + n - 1) % n;
        travelled += distanceUm(loop[j], loop[next]);
        j = next;
    }
    return loop[j];
}

/// Signed turn at vertex i in radians: positive = left turn (a convex corner of the material).
double turnAt(const Path& loop, std::size_t i, double reach) {
    const Point2& a = walk(loop, i, -1, reach);
    const Point2& b = loop[i];
    const Point2& c = walk(loop, i, +1, reach);
    const double ux = double(b.X - a.X), uy = double(b.Y - a.Y);
    const double vx = double(c.X - b.X), vy = double(c.Y - b.Y);
    return std::atan2(ux * vy - uy * vx, ux * vx + uy * vy);
}

double cornerScore(double turn, SeamCorner corner) {
    switch (corner) {
        case SeamCorner::Inner:
            return std::max(0.0, -turn);
        case SeamCorner::Outer:
            return std::max(0.0, turn);
        case SeamCorner::Any:
            return std::fabs(turn);
        case SeamCorner::Weighted:
            return std::max(0.0, -turn) + 0.5 * std::max(0.0, turn);
        case SeamCorner::None:
            break;
    }
    return 0.0;
}

bool moreBack(const Point2& a, const Point2& b) {
    return a.Y != b.Y ? a.Y > b.Y : a.X > b.X;
}

std::size_t sharpestCorner(const Path& loop, const SeamParams& params) {
    constexpr double kTie = 0.05;  // radians
    std::vector<double> score(loop.size());
    double best = 0;
    for (std::size_t i = 0; i < loop.size(); ++i) {
        score[i] = cornerScore(turnAt(loop, i, double(params.corner_lookaround_um)), params.corner);
        best = std::max(best, score[i]);
    }
    std::size_t chosen = 0;
    bool found = false;
    for (std::size_t i = 0; i < loop.size(); ++i) {
        if (score[i] < best - kTie)
            continue;
        if (!found || moreBack(loop[i], loop[chosen]))
            chosen = i;
        found = true;
    }
    return chosen;
}

/// CuraEngine 4.13's corner measure at vertex i from its two neighbours: the angle on the material's
/// side over pi, 0 … 2 (above 1 = a concave corner).
double leftAngleRatio(const Path& loop, std::size_t i) {
    const std::size_t n = loop.size();
    const Point2& a = loop[(i + n - 1) % n];
    const Point2& b = loop[i];
    const Point2& c = loop[(i + 1) % n];
    const double ux = double(b.X - a.X), uy = double(b.Y - a.Y);
    const double vx = double(c.X - b.X), vy = double(c.Y - b.Y);
    if ((ux == 0 && uy == 0) || (vx == 0 && vy == 0))
        return 1.0;
    return 1.0 - std::atan2(ux * vy - uy * vx, ux * vx + uy * vy) / std::numbers::pi;
}

/// How much a corner of `angle_ratio` (leftAngleRatio) is preferred, in units of the corner shift.
double cornerPull(double angle_ratio, SeamCorner corner) {
    const double bend = angle_ratio - 1.0;  // > 0 concave, < 0 convex
    switch (corner) {
        case SeamCorner::Inner:
            return std::max(0.0, bend);
        case SeamCorner::Outer:
            return std::max(0.0, -bend);
        case SeamCorner::Any:
            return std::fabs(bend);
        case SeamCorner::Weighted:
            return bend > 0 ? 2 * bend : -bend;
        case SeamCorner::None:
            break;
    }
    return 0.0;
}

bool moreBack(const Point2& a, const Point2& b);

/// The user-specified seam as CuraEngine 4.13 scores it: the squared distance to the seam point,
/// lessened by a tenth of itself times the corner pull; scores within 25 µm² tie, and ties go to
/// the back-most vertex.
std::size_t nearestWithCorners(const Path& loop, const Point2& target, SeamCorner corner) {
    constexpr double kEpsilonUm2 = 25;
    std::size_t chosen = 0;
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < loop.size(); ++i) {
        const double d = distanceUm(loop[i], target);
        const double score = d * d - cornerPull(leftAngleRatio(loop, i), corner) * d * d / 10;
        if (score < best - kEpsilonUm2 || (score <= best + kEpsilonUm2 && moreBack(loop[i], loop[chosen]))) {
            chosen = i;
            best = std::min(best, score);
        }
    }
    return chosen;
}

std::size_t nearestTo(const Path& loop, const Point2& target) {
    std::size_t chosen = 0;
    double best = distanceUm(loop[0], target);
    for (std::size_t i = 1; i < loop.size(); ++i) {
        const double d = distanceUm(loop[i], target);
        if (d < best - 0.5 || (d < best + 0.5 && moreBack(loop[i], loop[chosen]))) {
            best = std::min(best, d);
            chosen = i;
        }
    }
    return chosen;
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
    p.corner_lookaround_um = s.lengthMicrons(key::wall_line_width_0);
    return p;
}

std::size_t seamVertex(const Path& loop, const SeamParams& params, std::uint64_t seed) {
    if (loop.empty())
        return 0;
    switch (params.type) {
        case SeamType::Back:
            return nearestWithCorners(loop, params.position_um, params.corner);
        case SeamType::Random:
            return static_cast<std::size_t>(mix(seed) % loop.size());
        case SeamType::SharpestCorner:
            if (params.corner == SeamCorner::None)
                return nearestTo(loop, params.position_um);
            return sharpestCorner(loop, params);
        case SeamType::Shortest:
            break;
    }
    return 0;
}

void placeSeams(std::vector<ExtrusionPath>& paths, const SeamParams& params, int layer) {
    if (params.type == SeamType::Shortest)
        return;
    for (std::size_t i = 0; i < paths.size(); ++i) {
        ExtrusionPath& path = paths[i];
        if (!path.closed || path.points.empty())
            continue;
        const std::uint64_t seed = mix(static_cast<std::uint64_t>(layer)) ^ mix(i + 0x51ed27ULL);
        const std::size_t start = seamVertex(path.points, params, seed);
        std::rotate(path.points.begin(), path.points.begin() + static_cast<std::ptrdiff_t>(start),
                    path.points.end());
        path.fixed_start = true;
    }
}

}  // namespace mixengine
