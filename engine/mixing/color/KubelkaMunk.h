#pragma once
// The subtractive, pigment-style mixing model: single-constant Kubelka–Munk theory per band of a
// reflectance spectrum (mixing/color/Spectral.h). Each channel colour (mixing_channel_colors) gets a
// smooth reflectance spectrum ρ(λ); its absorption/scattering ratio is K/S = (1 − ρ)² / (2ρ); a
// mix with shares w_c has K/S = Σ w_c · K/S_c (concentrations add), and reflects
// ρ = 1 + K/S − √((K/S)² + 2·K/S). The concentration of a channel is its share weighted by its
// tinting strength, taken as (L*/100 + 0.01)² of its colour (as spectral.js weights by luminance
// squared): without it one strong absorber (a pure blue, black) swallows any mix, and equal
// shares would not look about halfway. Yellow and blue overlap in the green band, so they mix to
// green (linear RGB averaging would give grey); white lightens, black darkens.
#include <vector>

#include "mixing/color/ColorSpace.h"
#include "mixing/color/Spectral.h"
#include "planning/MixVector.h"

namespace mixengine {

class PigmentModel {
  public:
    /// One channel per colour (1..kMaxMixChannels colours).
    explicit PigmentModel(const std::vector<Rgb>& channel_colors);

    int channels() const { return static_cast<int>(ks_.size()); }
    /// The colour a mix is predicted to print (shares are normalised by their sum).
    Lab predictLab(const MixVector& mix) const;
    Rgb predictRgb(const MixVector& mix) const { return space_.srgbOf(predictLab(mix)); }
    const ColorSpace& space() const { return space_; }

  private:
    ColorSpace space_;
    SpectralObserver observer_;
    std::vector<Spectrum> ks_;     ///< K/S per band of each channel
    std::vector<double> tinting_;  ///< tinting strength of each channel
};

}  // namespace mixengine
