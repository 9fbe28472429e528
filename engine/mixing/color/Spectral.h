#pragma once
// Reflectance spectra for the pigment-style mixing model (mixing/color/KubelkaMunk.h).
//
// Documented model (no measured filament spectra are needed):
//   - 36 bands, 380..730 nm every 10 nm;
//   - observer: the CIE 1931 2° colour-matching functions in the analytic multi-lobe form of
//     Wyman, Sloan & Shirley, "Simple Analytic Approximations to the CIE XYZ Color Matching
//     Functions" (JCGT 2013);
//   - illuminant: D50 approximated by a 5003 K black body (Planck's law), the tristimulus values
//     scaled per component so that a perfect white reflector gives exactly the D50 white of
//     Little CMS (ColorSpace::whiteD50);
//   - a colour's reflectance: the smooth spectrum ρ(λ) = ½ + x / (2·√(1 + x²)),
//     x = c0 + c1·t + c2·t², t = (λ − 555 nm) / 175 nm (the sigmoid polynomial of Jakob & Hanika,
//     "A Low-Dimensional Function Space for Efficient Spectral Upsampling", 2019), its three
//     coefficients fitted (Levenberg–Marquardt) so that its CIELAB matches the colour's.
#include <array>

#include "mixing/color/ColorSpace.h"

namespace mixengine {

inline constexpr int kSpectralBands = 36;
using Spectrum = std::array<double, kSpectralBands>;

struct ReflectanceFit {
    Spectrum reflectance{};
    double delta_e00 = 0;  ///< between the fitted spectrum's colour and the wanted one
};

/// The observer × illuminant tables (immutable after construction, cheap to build).
class SpectralObserver {
  public:
    SpectralObserver();
    /// CIELAB of a reflectance spectrum under the model's D50 illuminant.
    Lab labOf(const Spectrum& reflectance) const;
    /// The smooth reflectance spectrum whose colour is nearest to `target`.
    ReflectanceFit fit(const Lab& target) const;

  private:
    Spectrum x_{}, y_{}, z_{};  ///< colour-matching functions × illuminant
    Xyz scale_{};               ///< per-component scale: white reflector → D50 white
};

}  // namespace mixengine
