#include "gcode/MixChannelSplit.h"

#include <algorithm>
#include <cmath>

namespace mixengine {

ChannelUnits MixChannelSplit::split(long long units, const MixVector& given_mix, bool carry) {
    ChannelUnits out{};
    if (units == 0)
        return out;
    // A mix without any share cannot say where material goes: it all comes from channel 0.
    const MixVector mix = given_mix.sum() > 0 ? given_mix : MixVector::only(0, given_mix.channels);
    const long long total = units < 0 ? -units : units;
    const double sum = mix.sum();
    const bool use_carry = carry && units > 0;
    if (use_carry && !(mix == carried_mix_)) {
        carry_ = {};
        carried_mix_ = mix;
    }
    std::array<double, kMaxMixChannels> exact{}, wanted{};
    long long given = 0;
    for (int c = 0; c < mix.channels; ++c) {
        const auto i = static_cast<std::size_t>(c);
        exact[i] = static_cast<double>(total) * std::max(0.0, mix[c]) / sum;
        if (exact[i] <= 0)
            continue;  // a channel without share gets nothing, whatever it was owed
        wanted[i] = std::clamp(exact[i] + (use_carry ? carry_[i] : 0.0), 0.0, static_cast<double>(total));
        out[i] = static_cast<long long>(std::floor(wanted[i]));
        given += out[i];
    }
    // Hand out (or take back) single units by how far each channel is from what it wants.
    while (given != total) {
        const bool add = given < total;
        int best = -1;
        double best_gap = 0;
        for (int c = 0; c < mix.channels; ++c) {
            const auto i = static_cast<std::size_t>(c);
            if (exact[i] <= 0 || (!add && out[i] == 0))
                continue;
            const double gap =
                add ? wanted[i] - static_cast<double>(out[i]) : static_cast<double>(out[i]) - wanted[i];
            if (best < 0 || gap > best_gap) {
                best = c;
                best_gap = gap;
            }
        }
        out[static_cast<std::size_t>(best)] += add ? 1 : -1;
        given += add ? 1 : -1;
    }
    for (int c = 0; c < mix.channels; ++c) {
        const auto i = static_cast<std::size_t>(c);
        if (use_carry)
            carry_[i] = exact[i] > 0 ? exact[i] + carry_[i] - static_cast<double>(out[i]) : 0.0;
        if (units < 0)
            out[i] = -out[i];
    }
    return out;
}

}  // namespace mixengine
