#pragma once
// The firmware's mix resolution: shares become whole multiples of 1/steps that still add up to
// exactly 1 (largest-remainder rounding; ties go to the lower channel). A mix command is written
// only when the quantised mix changes, so the resolution also decides how often that happens.
#include <array>

#include "planning/MixVector.h"

namespace mixengine {

/// Whole steps per channel, summing to `steps` (every share rounded to the nearest possible).
std::array<int, kMaxMixChannels> quantiseSteps(const MixVector& mix, int steps);

/// The quantised mix as fractions (steps / `steps`).
MixVector quantise(const MixVector& mix, int steps);

}  // namespace mixengine
