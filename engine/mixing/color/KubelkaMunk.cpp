#include "mixing/color/KubelkaMunk.h"

#include <algorithm>
#include <cmath>

namespace mixengine {
namespace {

/// Reflectances are kept off 0 and 1, where K/S is infinite or 0.
constexpr double kMinReflectance = 1e-6;

double ksOf(double reflectance) {
    const double r = std::clamp(reflectance, kMinReflectance, 1.0 - kMinReflectance);
    return (1.0 - r) * (1.0 - r) / (2.0 * r);
}

double reflectanceOf(double ks) {
    return 1.0 + ks - std::sqrt(ks * ks + 2.0 * ks);
}

}  // namespace

PigmentModel::PigmentModel(const std::vector<Rgb>& channel_colors) {
    for (const Rgb& color : channel_colors) {
        const Lab lab = space_.labOf(color);
        const ReflectanceFit fit = observer_.fit(lab);
        tinting_.push_back((lab.L / 100.0 + 0.01) * (lab.L / 100.0 + 0.01));
        Spectrum ks{};
        for (std::size_t k = 0; k < kSpectralBands; ++k)
            ks[k] = ksOf(fit.reflectance[k]);
        ks_.push_back(ks);
    }
}

Lab PigmentModel::predictLab(const MixVector& mix) const {
    double total = 0;
    auto strength = [&](int c) { return std::max(0.0, mix[c]) * tinting_[static_cast<std::size_t>(c)]; };
    for (int c = 0; c < channels(); ++c)
        total += strength(c);
    Spectrum ks{};
    for (int c = 0; c < channels(); ++c) {
        const double weight = total > 0 ? strength(c) / total : 1.0 / channels();
        for (std::size_t k = 0; k < kSpectralBands; ++k)
            ks[k] += weight * ks_[static_cast<std::size_t>(c)][k];
    }
    Spectrum reflectance{};
    for (std::size_t k = 0; k < kSpectralBands; ++k)
        reflectance[k] = reflectanceOf(ks[k]);
    return observer_.labOf(reflectance);
}

}  // namespace mixengine
