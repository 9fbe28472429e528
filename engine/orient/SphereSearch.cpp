#include "orient/SphereSearch.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "orient/Rotation.h"

namespace mixengine::orient {
namespace {

constexpr double kRad = std::numbers::pi / 180.0;

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
    return std::acos(std::clamp(dot(a, b), -1.0, 1.0)) / kRad;
}

/// Shrinking pattern search on the sphere around u, from 0.5° down to 0.01°.
DirectionCandidate refine(const DirectionFunction& v, Vec3 u, double value, SphereSearchStats& stats) {
    for (double step = 0.5; step >= 0.01;) {
        const auto [t1, t2] = tangentBasis(u);
        bool moved = false;
        for (const Vec3& dir : {t1, t1 * -1.0, t2, t2 * -1.0}) {
            const Vec3 trial = normalised(u * std::cos(step * kRad) + dir * std::sin(step * kRad));
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
        return normalised(e1 * std::cos(a_deg * kRad) + e2 * std::sin(a_deg * kRad));
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
    const double p = polar_deg * kRad, a = azimuth_deg * kRad;
    return {std::sin(p) * std::cos(a), std::sin(p) * std::sin(a), std::cos(p)};
}

std::vector<DirectionCandidate> searchSphere(const DirectionFunction& v,
                                             const std::vector<Vec3>& flat_normals,
                                             const SphereSearchOptions& options, SphereSearchStats& stats) {
    const int polar_n = static_cast<int>(std::lround(180.0 / options.grid_step_deg)) + 1;
    const int azimuth_n = static_cast<int>(std::lround(360.0 / options.grid_step_deg));
    std::vector<double> grid(static_cast<std::size_t>(polar_n) * azimuth_n);
    for (int p = 0; p < polar_n; ++p) {
        for (int a = 0; a < azimuth_n; ++a) {
            grid[p * azimuth_n + a] =
                v(sphericalDirection(p * options.grid_step_deg, a * options.grid_step_deg));
        }
    }
    stats.evaluations += grid.size();
    std::vector<Sample> minima;
    for (int p = 0; p < polar_n; ++p) {
        for (int a = 0; a < azimuth_n; ++a) {
            const double value = grid[p * azimuth_n + a];
            bool minimum = true;
            for (int dp = -1; dp <= 1 && minimum; ++dp) {
                for (int da = -1; da <= 1 && minimum; ++da) {
                    const int q = p + dp;
                    if (q < 0 || q >= polar_n || (dp == 0 && da == 0))
                        continue;
                    minimum = value <= grid[q * azimuth_n + (a + da + azimuth_n) % azimuth_n];
                }
            }
            if (minimum)
                minima.push_back({value, p, a});
        }
    }
    std::stable_sort(minima.begin(), minima.end(),
                     [](const Sample& x, const Sample& y) { return x.v < y.v; });
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
    std::vector<DirectionCandidate> result;
    for (const DirectionCandidate& k : kept)
        result.push_back(refine(v, k.u, k.v_estimate_mm3, stats));
    for (std::size_t n = 0; n < flat_normals.size(); ++n) {
        const bool same_circle =
            std::any_of(flat_normals.begin(), flat_normals.begin() + n, [&](const Vec3& m) {
                return std::abs(dot(m, flat_normals[n])) > std::cos(kRad);  // ±n: one great circle
            });
        if (same_circle)
            continue;
        DirectionCandidate c = circleMinimum(v, flat_normals[n], options.circle_step_deg, stats);
        c.source = "flat face " + std::to_string(n);
        c.flat_face = static_cast<int>(n);
        result.push_back(c);
    }
    return result;
}

}  // namespace mixengine::orient
