#include "gcode/mixdialect/MixChannelSplit.h"

#include <algorithm>
#include <cmath>

namespace mixengine {
namespace {

using ChannelAmounts = std::array<double, kMaxMixChannels>;

/// What one split works with: per channel, the exact share of the units, what it wants (the share
/// plus its carry), and the whole units it gets.
struct Shares {
    ChannelAmounts exact{};
    ChannelAmounts wanted{};
    ChannelUnits out{};
};

/// The channel that most wants one more unit (`add`) or best gives one back; channels without
/// share are never chosen, and none gives back below 0.
int neediestChannel(const Shares& s, int channels, bool add) {
    int best = -1;
    double best_gap = 0;
    for (int c = 0; c < channels; ++c) {
        const auto i = static_cast<std::size_t>(c);
        if (s.exact[i] <= 0 || (!add && s.out[i] == 0))
            continue;
        const double gap =
            add ? s.wanted[i] - static_cast<double>(s.out[i]) : static_cast<double>(s.out[i]) - s.wanted[i];
        if (best < 0 || gap > best_gap) {
            best = c;
            best_gap = gap;
        }
    }
    return best;
}

/// Hands out (or takes back) single units until the channels' units add up to `total`.
void settle(Shares& s, int channels, long long given, long long total) {
    while (given != total) {
        const bool add = given < total;
        s.out[static_cast<std::size_t>(neediestChannel(s, channels, add))] += add ? 1 : -1;
        given += add ? 1 : -1;
    }
}

}  // namespace

ChannelUnits MixChannelSplit::split(long long units, const MixVector& given_mix, bool carry) {
    if (units == 0)
        return ChannelUnits{};
    // A mix without any share cannot say where material goes: it all comes from channel 0.
    const MixVector mix = given_mix.sum() > 0 ? given_mix : MixVector::only(0, given_mix.channels);
    const long long total = units < 0 ? -units : units;
    const double sum = mix.sum();
    const bool use_carry = carry && units > 0;
    if (use_carry && !(mix == carried_mix_)) {
        carry_ = {};
        carried_mix_ = mix;
    }
    Shares s;
    long long given = 0;
    for (int c = 0; c < mix.channels; ++c) {
        const auto i = static_cast<std::size_t>(c);
        s.exact[i] = static_cast<double>(total) * std::max(0.0, mix[c]) / sum;
        if (s.exact[i] <= 0)
            continue;  // a channel without share gets nothing, whatever it was owed
        s.wanted[i] = std::clamp(s.exact[i] + (use_carry ? carry_[i] : 0.0), 0.0, static_cast<double>(total));
        s.out[i] = static_cast<long long>(std::floor(s.wanted[i]));
        given += s.out[i];
    }
    settle(s, mix.channels, given, total);
    for (int c = 0; c < mix.channels; ++c) {
        const auto i = static_cast<std::size_t>(c);
        if (use_carry)
            carry_[i] = s.exact[i] > 0 ? s.exact[i] + carry_[i] - static_cast<double>(s.out[i]) : 0.0;
        if (units < 0)
            s.out[i] = -s.out[i];
    }
    return s.out;
}

}  // namespace mixengine
