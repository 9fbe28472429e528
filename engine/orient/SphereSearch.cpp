#include "orient/SphereSearch.h"

#include <algorithm>
#include <cmath>

#include "geometry/Angles.h"
#include "orient/Rotation.h"

namespace mixengine::orient {
namespace {

struct Sample {
    double v;
    int polar, azimuth;
};

/// Two unit vectors perpendicular to u and to each other.
std::pair<Vec3, Vec3> tangentBasis(const Vec3& u) {
    const Vec3 helper = std::abs(u.z) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0};
    const Vec3 t1 = normalised(cross(u, helper));
    return {t1, cross(u, t1)};
}

double angleBetweenDeg(const Vec3& a, const Vec3& b) {
    return std::acos(std::clamp(dot(a, b), -1.0, 1.0)) / kRadiansPerDegree;
}

/// Shrinking pattern search on the sphere around u, from 0.5° down to 0.01°.
DirectionCandidate refine(const DirectionFunction& v, Vec3 u, double value, SphereSearchStats& stats) {
    for (double step = 0.5; step >= 0.01;) {
        const auto [t1, t2] = tangentBasis(u);
        bool moved = false;
        for (const Vec3& dir : {t1, t1 * -1.0, t2, t2 * -1.0}) {
            const Vec3 trial =
                normalised(u * std::cos(step * kRadiansPerDegree) + dir * std::sin(step * kRadiansPerDegree));
            const double tv = v(trial);
            ++stats.evaluations;
            if (tv < value) {
                u = trial, value = tv, moved = true;
                break;
            }
        }
        if (!moved)
            step *= 0.5;
    }
    return {u, value, "local minimum", -1};
}

/// The best direction on the great circle perpendicular to `normal`, refined to 0.01°.
DirectionCandidate circleMinimum(const DirectionFunction& v, const Vec3& normal, double step_deg,
                                 SphereSearchStats& stats) {
    const auto [e1, e2] = tangentBasis(normalised(normal));
    auto at = [&](double a_deg) {
        return normalised(e1 * std::cos(a_deg * kRadiansPerDegree) +
                          e2 * std::sin(a_deg * kRadiansPerDegree));
    };
    double best_angle = 0, best = v(at(0));
    for (double a = step_deg; a < 360.0; a += step_deg) {
        const double value = v(at(a));
        if (value < best)
            best = value, best_angle = a;
    }
    stats.evaluations += static_cast<std::size_t>(360.0 / step_deg);
    for (double step = step_deg * 0.5; step >= 0.01; step *= 0.5) {
        for (const double a : {best_angle - step, best_angle + step}) {
            const double value = v(at(a));
            ++stats.evaluations;
            if (value < best)
                best = value, best_angle = a;
        }
    }
    return {at(best_angle), best, "", -1};
}

}  // namespace

Vec3 sphericalDirection(double polar_deg, double azimuth_deg) {
    const double p = polar_deg * kRadiansPerDegree, a = azimuth_deg * kRadiansPerDegree;
    return {std::sin(p) * std::cos(a), std::sin(p) * std::sin(a), std::cos(p)};
}

namespace {

/// V on the grid of polar angle × azimuth, row (polar) by row.
struct SphereGrid {
    int polar_n = 0;
    int azimuth_n = 0;
    std::vector<double> values;

    double at(int p, int a) const { return values[p * azimuth_n + a]; }
};

SphereGrid sampleGrid(const DirectionFunction& v, double step_deg, SphereSearchStats& stats) {
    SphereGrid g;
    g.polar_n = static_cast<int>(std::lround(180.0 / step_deg)) + 1;
    g.azimuth_n = static_cast<int>(std::lround(360.0 / step_deg));
    g.values.resize(static_cast<std::size_t>(g.polar_n) * g.azimuth_n);
    for (int p = 0; p < g.polar_n; ++p) {
        for (int a = 0; a < g.azimuth_n; ++a)
            g.values[p * g.azimuth_n + a] = v(sphericalDirection(p * step_deg, a * step_deg));
    }
    stats.evaluations += g.values.size();
    return g;
}

/// No neighbour (8-neighbourhood; azimuth wraps, the poles' rows end) is lower.
bool isLocalMinimum(const SphereGrid& g, int p, int a) {
    const double value = g.at(p, a);
    for (int dp = -1; dp <= 1; ++dp) {
        const int q = p + dp;
        if (q < 0 || q >= g.polar_n)
            continue;
        for (int da = -1; da <= 1; ++da) {
            if ((dp != 0 || da != 0) && !(value <= g.at(q, (a + da + g.azimuth_n) % g.azimuth_n)))
                return false;
        }
    }
    return true;
}

/// The grid's local minima, lowest first (ties in grid order).
std::vector<Sample> localMinima(const SphereGrid& g) {
    std::vector<Sample> minima;
    for (int p = 0; p < g.polar_n; ++p) {
        for (int a = 0; a < g.azimuth_n; ++a) {
            if (isLocalMinimum(g, p, a))
                minima.push_back({g.at(p, a), p, a});
        }
    }
    std::stable_sort(minima.begin(), minima.end(),
                     [](const Sample& x, const Sample& y) { return x.v < y.v; });
    return minima;
}

/// The lowest minima, at most options.minima, each at least separation_deg from those kept before
/// it (and from their opposites when V is even).
std::vector<DirectionCandidate> separatedMinima(const std::vector<Sample>& minima,
                                                const SphereSearchOptions& options) {
    std::vector<DirectionCandidate> kept;
    for (const Sample& s : minima) {
        if (static_cast<int>(kept.size()) >= options.minima)
            break;
        const Vec3 u = sphericalDirection(s.polar * options.grid_step_deg, s.azimuth * options.grid_step_deg);
        const bool near = std::any_of(kept.begin(), kept.end(), [&](const DirectionCandidate& k) {
            return angleBetweenDeg(k.u, u) < options.separation_deg ||
                   (options.even && angleBetweenDeg(k.u, u * -1.0) < options.separation_deg);
        });
        if (!near)
            kept.push_back({u, s.v, "", -1});
    }
    return kept;
}

/// The great-circle candidate of each flat face whose circle no earlier face shares.
void appendFlatFaceCandidates(const DirectionFunction& v, const std::vector<Vec3>& flat_normals,
                              const SphereSearchOptions& options, SphereSearchStats& stats,
                              std::vector<DirectionCandidate>& result) {
    for (std::size_t n = 0; n < flat_normals.size(); ++n) {
        const bool same_circle =
            std::any_of(flat_normals.begin(), flat_normals.begin() + n, [&](const Vec3& m) {
                return std::abs(dot(m, flat_normals[n])) >
                       std::cos(kRadiansPerDegree);  // ±n: one great circle
            });
        if (same_circle)
            continue;
        DirectionCandidate c = circleMinimum(v, flat_normals[n], options.circle_step_deg, stats);
        c.source = "flat face " + std::to_string(n);
        c.flat_face = static_cast<int>(n);
        result.push_back(c);
    }
}

}  // namespace

std::vector<DirectionCandidate> searchSphere(const DirectionFunction& v,
                                             const std::vector<Vec3>& flat_normals,
                                             const SphereSearchOptions& options, SphereSearchStats& stats) {
    const SphereGrid grid = sampleGrid(v, options.grid_step_deg, stats);
    std::vector<DirectionCandidate> result;
    for (const DirectionCandidate& k : separatedMinima(localMinima(grid), options))
        result.push_back(refine(v, k.u, k.v_estimate_mm3, stats));
    appendFlatFaceCandidates(v, flat_normals, options, stats, result);
    return result;
}

}  // namespace mixengine::orient
