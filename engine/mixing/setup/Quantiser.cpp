#include "mixing/setup/Quantiser.h"

#include <algorithm>
#include <cmath>

namespace mixengine {

std::array<int, kMaxMixChannels> quantiseSteps(const MixVector& mix, int steps) {
    std::array<int, kMaxMixChannels> whole{};
    std::array<double, kMaxMixChannels> remainder{};
    const double sum = mix.sum() > 0 ? mix.sum() : 1.0;  // shares add up to 1; guard rounding drift
    int given = 0;
    for (int c = 0; c < mix.channels; ++c) {
        const double exact = std::max(0.0, mix[c]) / sum * steps;
        const auto i = static_cast<std::size_t>(c);
        whole[i] = static_cast<int>(std::floor(exact));
        remainder[i] = exact - whole[i];
        given += whole[i];
    }
    // Hand out the missing steps to the largest remainders (stable: lower channel first on ties).
    std::array<int, kMaxMixChannels> order{0, 1, 2, 3, 4};
    std::stable_sort(order.begin(), order.begin() + mix.channels, [&](int a, int b) {
        return remainder[static_cast<std::size_t>(a)] > remainder[static_cast<std::size_t>(b)];
    });
    for (int k = 0; given < steps && k < mix.channels; ++k, ++given)
        ++whole[static_cast<std::size_t>(order[static_cast<std::size_t>(k)])];
    return whole;
}

MixVector quantise(const MixVector& mix, int steps) {
    const auto whole = quantiseSteps(mix, steps);
    MixVector q;
    q.channels = mix.channels;
    for (int c = 0; c < mix.channels; ++c)
        q[c] = static_cast<double>(whole[static_cast<std::size_t>(c)]) / steps;
    return q;
}

}  // namespace mixengine
