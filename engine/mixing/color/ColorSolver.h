#pragma once
// Target colour → channel ratios: the mix whose predicted colour (mixing/color/KubelkaMunk.h) is
// nearest to the target in CIEDE2000. Search: every mix on a grid over the simplex of shares
// (step 1/20 for up to 3 channels, 1/12 for 4, 1/10 for 5), then from the best grid mix, moves of
// a share δ from one channel to another while ΔE00 falls, δ halved from 1/20 down to 1e-6.
// Deterministic; a target equal to a channel colour gives 100 % of that channel.
#include "mixing/color/KubelkaMunk.h"

namespace mixengine {

/// ΔE00 above which a target counts as outside the mixable gamut (warned about).
inline constexpr double kGamutWarningDeltaE00 = 2.0;

struct ColorSolution {
    MixVector mix;
    Lab predicted;
    Rgb predicted_rgb{};
    double delta_e00 = 0;  ///< between the predicted colour and the target
};

ColorSolution solveColor(const PigmentModel& model, const Lab& target);
ColorSolution solveColor(const PigmentModel& model, const Rgb& target);

}  // namespace mixengine
