#include "toolpaths/infill/GyroidInfill.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/PolygonOps.h"

namespace mixengine {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr int kSamplesPerPeriod = 16;

/// The box [u0, u1] × [v0, v1] in radians of the gyroid.
struct Family {
    double u0, u1, v0, v1;
};

/// The curves v(u) solving a(u)·cos v + b(u)·sin v = -c(u) (coeffs(u) gives {a, b, c}) that cross
/// the box, as (u, v) samples in radians.
template <typename Coeffs>
std::vector<std::vector<std::pair<double, double>>> solveFamily(const Family& box, Coeffs coeffs) {
    const double step = kTwoPi / kSamplesPerPeriod;
    const long first = static_cast<long>(std::floor(box.u0 / step));
    const long last = static_cast<long>(std::ceil(box.u1 / step));
    // Per sample: the phase phi (unwrapped along u so that the curves stay continuous) and the
    // half-opening of the two branches, v = phi ± base (+ 2πm).
    std::vector<double> us, phis, bases;
    for (long i = first; i <= last; ++i) {
        const double u = double(i) * step;
        const auto [a, b, c] = coeffs(u);
        double phi = std::atan2(b, a);
        if (!phis.empty())
            phi += kTwoPi * std::round((phis.back() - phi) / kTwoPi);
        us.push_back(u);
        phis.push_back(phi);
        bases.push_back(std::acos(std::clamp(-c / std::hypot(a, b), -1.0, 1.0)));
    }
    const auto [lo, hi] = std::minmax_element(phis.begin(), phis.end());
    const long m_first = static_cast<long>(std::floor((box.v0 - *hi) / kTwoPi)) - 1;
    const long m_last = static_cast<long>(std::ceil((box.v1 - *lo) / kTwoPi)) + 1;
    std::vector<std::vector<std::pair<double, double>>> curves;
    for (int sign : {-1, 1}) {
        for (long m = m_first; m <= m_last; ++m) {
            std::vector<std::pair<double, double>> curve;
            for (std::size_t i = 0; i < us.size(); ++i)
                curve.emplace_back(us[i], phis[i] + sign * bases[i] + kTwoPi * double(m));
            curves.push_back(std::move(curve));
        }
    }
    return curves;
}

}  // namespace

Paths gyroidCurves(const Paths& area, coord_um period_um, coord_um z_um) {
    if (period_um <= 0 || area.empty())
        return {};
    const double k = kTwoPi / double(period_um);  // radians per micron
    const Box2 box = boundsOf(area);
    const double zr = k * double(z_um);
    const double sin_z = std::sin(zr), cos_z = std::cos(zr);
    const bool y_of_x = std::fabs(cos_z) >= std::fabs(sin_z);
    Paths lines;
    auto emit = [&](const std::vector<std::vector<std::pair<double, double>>>& curves, bool swap) {
        for (const auto& curve : curves) {
            Path line;
            for (const auto& [u, v] : curve) {
                const coord_um pu = static_cast<coord_um>(std::llround(u / k));
                const coord_um pv = static_cast<coord_um>(std::llround(v / k));
                line.push_back(swap ? Point2{pv, pu} : Point2{pu, pv});
            }
            lines.push_back(std::move(line));
        }
    };
    if (y_of_x) {
        // sin X·cos Y + cos Z·sin Y = -sin Z·cos X
        const Family f{k * double(box.left), k * double(box.right), k * double(box.top),
                       k * double(box.bottom)};
        emit(solveFamily(f,
                         [&](double x) {
                             return std::tuple{std::sin(x), cos_z, sin_z * std::cos(x)};
                         }),
             false);
    } else {
        // sin Z·cos X + cos Y·sin X = -cos Z·sin Y
        const Family f{k * double(box.top), k * double(box.bottom), k * double(box.left),
                       k * double(box.right)};
        emit(solveFamily(f,
                         [&](double y) {
                             return std::tuple{sin_z, std::cos(y), cos_z * std::sin(y)};
                         }),
             true);
    }
    return clipLines(lines, area);
}

}  // namespace mixengine
