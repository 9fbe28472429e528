#include "mixing/color/ColorSolver.h"

#include <vector>

namespace mixengine {
namespace {

int gridSteps(int channels) {
    if (channels <= 3)
        return 20;
    return channels == 4 ? 12 : 10;
}

/// Calls `visit` with every mix of `channels` shares in multiples of 1/steps.
template <typename Visit>
void forEachGridMix(int channels, int steps, Visit&& visit) {
    std::vector<int> parts(static_cast<std::size_t>(channels), 0);
    auto recurse = [&](auto&& self, int channel, int left) -> void {
        if (channel == channels - 1) {
            parts[static_cast<std::size_t>(channel)] = left;
            MixVector mix;
            mix.channels = channels;
            for (int c = 0; c < channels; ++c)
                mix[c] = static_cast<double>(parts[static_cast<std::size_t>(c)]) / steps;
            visit(mix);
            return;
        }
        for (int p = 0; p <= left; ++p) {
            parts[static_cast<std::size_t>(channel)] = p;
            self(self, channel + 1, left - p);
        }
    };
    recurse(recurse, 0, steps);
}

struct Candidate {
    MixVector mix;
    double delta_e00 = 0;
};

/// Moves of δ between every ordered pair of channels while they lower ΔE00.
bool improveByTransfers(const PigmentModel& model, const Lab& target, double delta, Candidate& best) {
    bool improved = false;
    for (int from = 0; from < best.mix.channels; ++from) {
        for (int to = 0; to < best.mix.channels; ++to) {
            if (from == to || best.mix[from] <= 0)
                continue;
            MixVector mix = best.mix;
            const double moved = std::min(delta, mix[from]);
            mix[from] -= moved;
            mix[to] += moved;
            const double de = deltaE00(model.predictLab(mix), target);
            if (de < best.delta_e00) {
                best = {mix, de};
                improved = true;
            }
        }
    }
    return improved;
}

}  // namespace

ColorSolution solveColor(const PigmentModel& model, const Lab& target) {
    const int channels = model.channels();
    Candidate best{MixVector::only(0, channels),
                   deltaE00(model.predictLab(MixVector::only(0, channels)), target)};
    forEachGridMix(channels, gridSteps(channels), [&](const MixVector& mix) {
        const double de = deltaE00(model.predictLab(mix), target);
        if (de < best.delta_e00)
            best = {mix, de};
    });
    for (double delta = 1.0 / 20; delta >= 1e-6; delta /= 2) {
        for (int round = 0; round < 64 && improveByTransfers(model, target, delta, best); ++round) {
        }
    }
    ColorSolution solution;
    solution.mix = best.mix;
    solution.predicted = model.predictLab(best.mix);
    solution.predicted_rgb = model.space().srgbOf(solution.predicted);
    solution.delta_e00 = best.delta_e00;
    return solution;
}

ColorSolution solveColor(const PigmentModel& model, const Rgb& target) {
    return solveColor(model, model.space().labOf(target));
}

}  // namespace mixengine
