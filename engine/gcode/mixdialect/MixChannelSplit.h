#pragma once
// Splits the written units of one move (1e-5 mm each) over the filament channels of a mix: whole
// units, never negative for a forward move, adding up exactly to the move's units — so the
// channel words of a move sum to the single-colour E word (seed 001: B = total − A). With carry
// on, what rounding takes from a channel on one move is given back on later moves (error
// diffusion), so each channel's running total stays within about one unit of its exact share. The
// carry belongs to one mix: a different mix starts afresh, so the amounts laid with each mix (one
// mesh, one layer) add up to their exact shares within a unit.
#include <array>

#include "planning/MixVector.h"

namespace mixengine {

using ChannelUnits = std::array<long long, kMaxMixChannels>;

class MixChannelSplit {
  public:
    /// `units` may be negative (a retraction): the split is mirrored and carries nothing.
    ChannelUnits split(long long units, const MixVector& mix, bool carry = true);

  private:
    std::array<double, kMaxMixChannels> carry_{};
    MixVector carried_mix_;  ///< the mix the carry belongs to
};

}  // namespace mixengine
