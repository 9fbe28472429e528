#include "mixing/color/Spectral.h"

#include <algorithm>
#include <cmath>

namespace mixengine {
namespace {

constexpr double kFirstNm = 380;
constexpr double kStepNm = 10;
constexpr double kBlackBodyK = 5003;
constexpr double kSecondRadiationConstantMK = 1.4387769e-2;

/// One piecewise Gaussian lobe: width `below_nm` left of `peak_nm`, `above_nm` right of it.
double lobe(double nm, double peak_nm, double below_nm, double above_nm) {
    const double t = (nm - peak_nm) / (nm < peak_nm ? below_nm : above_nm);
    return std::exp(-0.5 * t * t);
}

using Coefficients = std::array<double, 3>;

Spectrum sigmoidPolynomial(const Coefficients& c) {
    Spectrum s{};
    for (int i = 0; i < kSpectralBands; ++i) {
        const double t = (kFirstNm + kStepNm * i - 555.0) / 175.0;
        const double x = c[0] + c[1] * t + c[2] * t * t;
        s[static_cast<std::size_t>(i)] = 0.5 + x / (2.0 * std::sqrt(1.0 + x * x));
    }
    return s;
}

std::array<double, 3> residual(const SpectralObserver& o, const Coefficients& c, const Lab& target) {
    const Lab lab = o.labOf(sigmoidPolynomial(c));
    return {lab.L - target.L, lab.a - target.a, lab.b - target.b};
}

double squared(const std::array<double, 3>& r) {
    return r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
}

/// Solves the 3×3 system a·x = b (Cramer's rule; a is symmetric positive definite here).
std::array<double, 3> solve3(const std::array<std::array<double, 3>, 3>& a, const std::array<double, 3>& b) {
    auto det = [](const std::array<std::array<double, 3>, 3>& m) {
        return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
               m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
               m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    };
    const double d = det(a);
    std::array<double, 3> x{};
    for (std::size_t col = 0; col < 3; ++col) {
        auto m = a;
        for (std::size_t row = 0; row < 3; ++row)
            m[row][col] = b[row];
        x[col] = d != 0 ? det(m) / d : 0;
    }
    return x;
}

/// One Levenberg–Marquardt step from `c`: the damped Gauss–Newton update (numeric Jacobian).
Coefficients dampedStep(const SpectralObserver& o, const Coefficients& c, const Lab& target,
                        const std::array<double, 3>& r, double damping) {
    constexpr double kH = 1e-5;
    std::array<std::array<double, 3>, 3> jacobian{};  // jacobian[i][j] = d r_i / d c_j
    for (std::size_t j = 0; j < 3; ++j) {
        Coefficients moved = c;
        moved[j] += kH;
        const auto rj = residual(o, moved, target);
        for (std::size_t i = 0; i < 3; ++i)
            jacobian[i][j] = (rj[i] - r[i]) / kH;
    }
    std::array<std::array<double, 3>, 3> normal{};
    std::array<double, 3> gradient{};
    for (std::size_t a = 0; a < 3; ++a) {
        for (std::size_t b = 0; b < 3; ++b) {
            for (std::size_t i = 0; i < 3; ++i)
                normal[a][b] += jacobian[i][a] * jacobian[i][b];
        }
        normal[a][a] *= 1.0 + damping;
        normal[a][a] += 1e-12;
        for (std::size_t i = 0; i < 3; ++i)
            gradient[a] -= jacobian[i][a] * r[i];
    }
    const auto delta = solve3(normal, gradient);
    return {c[0] + delta[0], c[1] + delta[1], c[2] + delta[2]};
}

}  // namespace

SpectralObserver::SpectralObserver() {
    for (int i = 0; i < kSpectralBands; ++i) {
        const double nm = kFirstNm + kStepNm * i;
        const double m = nm * 1e-9;
        const double power =
            1.0 / (std::pow(m, 5) * (std::exp(kSecondRadiationConstantMK / (m * kBlackBodyK)) - 1));
        const auto k = static_cast<std::size_t>(i);
        x_[k] = power * (1.056 * lobe(nm, 599.8, 37.9, 31.0) + 0.362 * lobe(nm, 442.0, 16.0, 26.7) -
                         0.065 * lobe(nm, 501.1, 20.4, 26.2));
        y_[k] = power * (0.821 * lobe(nm, 568.8, 46.9, 40.5) + 0.286 * lobe(nm, 530.9, 16.3, 31.1));
        z_[k] = power * (1.217 * lobe(nm, 437.0, 11.8, 36.0) + 0.681 * lobe(nm, 459.0, 26.0, 13.8));
    }
    Xyz white;
    for (std::size_t k = 0; k < kSpectralBands; ++k) {
        white.X += x_[k];
        white.Y += y_[k];
        white.Z += z_[k];
    }
    const Xyz d50 = ColorSpace::whiteD50();
    scale_ = {d50.X / white.X, d50.Y / white.Y, d50.Z / white.Z};
}

Lab SpectralObserver::labOf(const Spectrum& reflectance) const {
    Xyz xyz;
    for (std::size_t k = 0; k < kSpectralBands; ++k) {
        xyz.X += reflectance[k] * x_[k];
        xyz.Y += reflectance[k] * y_[k];
        xyz.Z += reflectance[k] * z_[k];
    }
    return ColorSpace::labOfXyz({xyz.X * scale_.X, xyz.Y * scale_.Y, xyz.Z * scale_.Z});
}

ReflectanceFit SpectralObserver::fit(const Lab& target) const {
    constexpr int kIterations = 300;
    Coefficients c{0, 0, 0};
    auto r = residual(*this, c, target);
    double error = squared(r);
    double damping = 1e-3;
    for (int i = 0; i < kIterations && error > 1e-12 && damping < 1e12; ++i) {
        const Coefficients next = dampedStep(*this, c, target, r, damping);
        const auto next_r = residual(*this, next, target);
        if (squared(next_r) < error) {
            c = next;
            r = next_r;
            error = squared(r);
            damping = std::max(damping * 0.3, 1e-9);
        } else {
            damping *= 10;
        }
    }
    ReflectanceFit result;
    result.reflectance = sigmoidPolynomial(c);
    result.delta_e00 = deltaE00(labOf(result.reflectance), target);
    return result;
}

}  // namespace mixengine
