#pragma once
// A mix: the share of each filament channel in the material leaving a mixing nozzle. Shares are
// fractions (0..1) that add up to 1; channel 0 is filament A (E), channel 1 filament B, and so on
// up to five channels (CMYK + white, as seed 001 plans). Plain value type, compared exactly.
// It lives with the plan (planning/LayerPlan.h: PrintPlan::mixes) because the plan carries the
// mixes: the mixing stage (mixing/MixingPass.h) fills them and the G-code writer reads them, both
// above planning in the pipeline.
#include <array>
#include <cstddef>

namespace mixengine {

inline constexpr int kMaxMixChannels = 5;

struct MixVector {
    std::array<double, kMaxMixChannels> share{};
    int channels = 1;  ///< channels in use (1..kMaxMixChannels); shares beyond are 0

    /// All material from `channel`.
    static MixVector only(int channel, int channel_count) {
        MixVector mix;
        mix.channels = channel_count;
        mix.share[static_cast<std::size_t>(channel)] = 1.0;
        return mix;
    }
    double operator[](int channel) const { return share[static_cast<std::size_t>(channel)]; }
    double& operator[](int channel) { return share[static_cast<std::size_t>(channel)]; }
    double sum() const {
        double total = 0;
        for (double s : share)
            total += s;
        return total;
    }
    bool operator==(const MixVector&) const = default;
};

}  // namespace mixengine
