#include "toolpaths/support/SupportSmoothing.h"

#include <algorithm>
#include <cmath>

#include "geometry/Angles.h"

namespace mixengine {
namespace {

struct Vec {
    double x = 0, y = 0;
};

Vec minus(const Point2& a, const Point2& b) {
    return {double(a.X - b.X), double(a.Y - b.Y)};
}

double norm(const Vec& v) {
    return std::hypot(v.x, v.y);
}

Point2 offsetBy(const Point2& p, const Vec& unit, double distance) {
    return {p.X + static_cast<coord_um>(std::llround(unit.x * distance)),
            p.Y + static_cast<coord_um>(std::llround(unit.y * distance))};
}

/// The corner p1 between p0 and p2 bends into the area (p1 lies left of p0 → p2).
bool isNotch(const Point2& p0, const Point2& p1, const Point2& p2) {
    const Vec chord = minus(p2, p0);
    const Vec to_corner = minus(p1, p0);
    return chord.x * to_corner.y - chord.y * to_corner.x > 0;
}

/// The distance along `from → towards` (a unit direction from `from`) at which a point lies
/// `reach` away from `centre`, the far solution; negative when there is none.
double reachAlong(const Point2& from, const Vec& towards, const Point2& centre, double reach) {
    const Vec rel = minus(from, centre);
    const double b = rel.x * towards.x + rel.y * towards.y;
    const double c = rel.x * rel.x + rel.y * rel.y - reach * reach;
    const double disc = b * b - c;
    return disc < 0 ? -1.0 : -b + std::sqrt(disc);
}

/// The points that replace the notch corner p1 (see the header).
Path shortcut(const Point2& p0, const Point2& p1, const Point2& p2, double cos_angle, double length) {
    const Vec v10 = minus(p0, p1), v12 = minus(p2, p1);
    const double l10 = norm(v10), l12 = norm(v12);
    if (norm(minus(p2, p0)) <= length)
        return {};
    const Vec u10{v10.x / l10, v10.y / l10}, u12{v12.x / l12, v12.y / l12};
    const double half = std::acos(std::clamp(cos_angle, -1.0, 1.0)) / 2;
    const double leg = length / 2 / std::sin(half);
    if (leg < l10 && leg < l12)
        return {offsetBy(p1, u10, leg), offsetBy(p1, u12, leg)};
    if (l12 < l10) {  // from p2 back to the edge p1 → p0
        const double at = reachAlong(p1, u10, p2, length);
        return at > 0 && at < l10 ? Path{offsetBy(p1, u10, at)} : Path{};
    }
    const double at = reachAlong(p1, u12, p0, length);
    return at > 0 && at < l12 ? Path{offsetBy(p1, u12, at)} : Path{};
}

/// The loop without points closer than 10 µm to the one before them.
Path withoutDuplicates(const Path& loop) {
    Path out;
    for (const Point2& p : loop) {
        if (out.empty() || norm(minus(p, out.back())) >= 10)
            out.push_back(p);
    }
    while (out.size() > 1 && norm(minus(out.front(), out.back())) < 10)
        out.pop_back();
    return out;
}

/// Each corner in turn, with the corner before it as already smoothed.
Path smoothLoop(const Path& loop, double cos_max, double length) {
    const std::size_t n = loop.size();
    Path out;
    for (std::size_t k = 0; k < n; ++k) {
        const Point2& p0 = out.empty() ? loop[n - 1] : out.back();
        const Point2& p1 = loop[k];
        const Point2& p2 = loop[(k + 1) % n];
        const Vec v10 = minus(p0, p1), v12 = minus(p2, p1);
        const double l10 = norm(v10), l12 = norm(v12);
        const bool degenerate = l10 == 0 || l12 == 0;
        const double cos_angle = degenerate ? 1.0 : (v10.x * v12.x + v10.y * v12.y) / (l10 * l12);
        if (degenerate || cos_angle <= cos_max || !isNotch(p0, p1, p2)) {
            out.push_back(p1);
            continue;
        }
        const Path replaced = shortcut(p0, p1, p2, cos_angle, length);
        out.insert(out.end(), replaced.begin(), replaced.end());
    }
    return out;
}

}  // namespace

Paths smoothOutward(const Paths& areas, double max_angle_degrees, coord_um shortcut_um) {
    if (shortcut_um <= 0)
        return areas;
    const double cos_max = std::cos(radiansFromDegrees(max_angle_degrees));
    Paths out;
    for (const Path& loop : areas) {
        if (loop.size() <= 3) {
            out.push_back(loop);
            continue;
        }
        const Path clean = withoutDuplicates(loop);
        Path smooth = clean.size() > 3 ? smoothLoop(clean, cos_max, double(shortcut_um)) : clean;
        if (smooth.size() >= 3)
            out.push_back(std::move(smooth));
    }
    return out;
}

}  // namespace mixengine
