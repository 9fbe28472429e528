#pragma once
// The physical mixing chamber (issue 26): the melt between the point where the filaments meet and
// the nozzle tip, modelled as `stages` equal stirred tanks in series holding `volume_mm3` together
// (stages → ∞ is plug flow). Only net new filament moves the melt: the caller pushes extruded
// volumes, never retractions. Each tank's content is a mix; a push of volume v with a constant inlet
// mix m advances the chain by τ = v / (volume_mm3 / stages) and has the closed form (d = content − m,
// tanks 1..N, d_0 = 0):
//   d_k(τ) = e^(−τ) Σ_{j≤k} d_j(0) τ^(k−j) / (k−j)!
// and what leaves over the push averages d_N over τ: Σ_j d_j(0) P(N−j+1, τ) / τ, P the regularised
// lower incomplete gamma function. Exact for any push length; no time stepping.
//
// Distances between mixes are the largest difference of any channel's share (shareDistance): the
// unit of mixing_transition_tolerance ("within 0.1 of the asked share").
#include <vector>

#include "planning/MixVector.h"

namespace mixengine {

struct ChamberSpec {
    double volume_mm3 = 0;  ///< mixing_chamber_volume; 0 = ideal (what is commanded leaves at once)
    int stages = 3;         ///< mixing_chamber_stages (≥ 1)
    bool ideal() const { return volume_mm3 <= 0; }
};

/// e^(−τ) τ^i / i! for i = 0..count−1 (the Poisson weights of a push of τ tank volumes); past the mode,
/// weights below 1e-17 are left 0. Computed in log space so no term overflows.
std::vector<double> poissonWeights(double tau, int count);
/// P(n, τ) = 1 − Σ_{i<n} e^(−τ) τ^i / i! (the regularised lower incomplete gamma function) for
/// n = 1..weights.size(), from poissonWeights(τ, …): element n − 1 is P(n, τ).
std::vector<double> gammaP(const std::vector<double>& weights);

/// max_c |a_c − b_c|.
double shareDistance(const MixVector& a, const MixVector& b);

class Chamber {
  public:
    /// A chamber full of `initial` (the print's first mix: the start code primes it).
    Chamber(ChamberSpec spec, const MixVector& initial);

    /// Pushes `volume_mm3` of `inlet` through; returns the average mix that left the nozzle during
    /// the push (`inlet` itself for an ideal chamber; the current outlet for a zero volume).
    MixVector push(const MixVector& inlet, double volume_mm3);
    /// The mix leaving the nozzle at this moment.
    MixVector outlet() const;
    /// The volume of a constant `inlet` after which the outlet is and stays within `tolerance`
    /// (shareDistance) of `inlet`; 0 when it already is. Precise to 0.01 mm³.
    double volumeToReach(const MixVector& inlet, double tolerance) const;
    const ChamberSpec& spec() const { return spec_; }
    /// The tanks' contents, from the inlet to the nozzle.
    const std::vector<MixVector>& tanks() const { return tanks_; }

  private:
    ChamberSpec spec_;
    std::vector<MixVector> tanks_;  ///< from the inlet (0) to the nozzle (stages − 1)
    int channels_ = 1;
};

/// The volume a change from one filament alone to another alone needs before the outlet is within
/// `tolerance` of the new one (the physical minimum of one change; 71 mm³ for 40 mm³ in 3 stages at 0.1).
double fullChangeVolumeMm3(const ChamberSpec& spec, double tolerance);

}  // namespace mixengine
