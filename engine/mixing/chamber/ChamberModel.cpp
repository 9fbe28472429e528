#include "mixing/chamber/ChamberModel.h"

#include <algorithm>
#include <cmath>

namespace mixengine {
namespace {

MixVector plus(const MixVector& base, const MixVector& delta, int channels) {
    MixVector out = base;
    for (int c = 0; c < channels; ++c)
        out[c] = base[c] + delta[c];
    return out;
}

MixVector difference(const MixVector& a, const MixVector& b, int channels) {
    MixVector d;
    d.channels = channels;
    for (int c = 0; c < channels; ++c)
        d[c] = a[c] - b[c];
    return d;
}

}  // namespace

std::vector<double> poissonWeights(double tau, int count) {
    std::vector<double> w(static_cast<std::size_t>(count), 0.0);
    if (tau <= 0) {
        if (count > 0)
            w[0] = 1.0;
        return w;
    }
    const double log_tau = std::log(tau);
    double log_w = -tau;  // log of e^(−τ) τ^i / i!, term by term
    for (int i = 0; i < count; ++i) {
        if (i > 0)
            log_w += log_tau - std::log(static_cast<double>(i));
        w[static_cast<std::size_t>(i)] = std::exp(log_w);
        if (i > tau && log_w < -40)
            break;  // past the mode and below 1e-17: the rest are smaller still (left 0)
    }
    return w;
}

std::vector<double> gammaP(const std::vector<double>& weights) {
    std::vector<double> p(weights.size());
    double below = 0;
    for (std::size_t n = 0; n < weights.size(); ++n) {
        below += weights[n];
        p[n] = std::max(0.0, 1.0 - below);  // p[n] = P(n + 1, τ)
    }
    return p;
}

double shareDistance(const MixVector& a, const MixVector& b) {
    double worst = 0;
    for (int c = 0; c < kMaxMixChannels; ++c)
        worst = std::max(worst, std::abs(a[c] - b[c]));
    return worst;
}

Chamber::Chamber(ChamberSpec spec, const MixVector& initial)
    : spec_(spec),
      tanks_(static_cast<std::size_t>(std::max(1, spec.stages)), initial),
      channels_(initial.channels) {
    spec_.stages = std::max(1, spec.stages);
}

MixVector Chamber::outlet() const {
    return tanks_.back();
}

MixVector Chamber::push(const MixVector& inlet, double volume_mm3) {
    if (spec_.ideal()) {
        std::fill(tanks_.begin(), tanks_.end(), inlet);
        return inlet;
    }
    if (volume_mm3 <= 0)
        return outlet();
    const int n = spec_.stages;
    const double tau = volume_mm3 * n / spec_.volume_mm3;
    const std::vector<double> w = poissonWeights(tau, n);
    const std::vector<double> p = gammaP(w);
    std::vector<MixVector> d(tanks_.size());
    for (std::size_t k = 0; k < tanks_.size(); ++k)
        d[k] = difference(tanks_[k], inlet, channels_);
    MixVector left_delta;  // the average of d_N over the push
    left_delta.channels = channels_;
    for (int j = 0; j < n; ++j)
        for (int c = 0; c < channels_; ++c)
            left_delta[c] += d[static_cast<std::size_t>(j)][c] * p[static_cast<std::size_t>(n - 1 - j)] / tau;
    // Poisson weights past the mode that fell below 1e-17 add nothing: a short push (τ ≪ 1, most extrusions)
    // mixes each tank with its few neighbours upstream only, so a long chain costs O(N), not O(N²).
    int reach = n - 1;
    for (int i = static_cast<int>(tau) + 1; i < n; ++i)
        if (w[static_cast<std::size_t>(i)] < 1e-17) {
            reach = i;
            break;
        }
    for (int k = n - 1; k >= 0; --k) {
        MixVector next;
        next.channels = channels_;
        for (int j = std::max(0, k - reach); j <= k; ++j)
            for (int c = 0; c < channels_; ++c)
                next[c] += d[static_cast<std::size_t>(j)][c] * w[static_cast<std::size_t>(k - j)];
        tanks_[static_cast<std::size_t>(k)] = plus(inlet, next, channels_);
    }
    return plus(inlet, left_delta, channels_);
}

double Chamber::volumeToReach(const MixVector& inlet, double tolerance) const {
    // settled: every tank within the tolerance (the outlet only stays close when none upstream is farther
    // off)
    const bool settled = std::all_of(tanks_.begin(), tanks_.end(), [&](const MixVector& tank) {
        return shareDistance(tank, inlet) <= tolerance;
    });
    if (spec_.ideal() || settled)
        return 0;
    // Bisection on the volume: the outlet of a chain whose tanks all lie on one side converges
    // monotonically; mixed histories may overshoot once, so the search asks for the outlet to be within
    // the tolerance at the found volume and a quarter chamber later.
    auto close = [&](double v) {
        for (double extra : {0.0, spec_.volume_mm3 / 4.0}) {
            Chamber probe = *this;
            probe.push(inlet, v + extra);
            if (shareDistance(probe.outlet(), inlet) > tolerance)
                return false;
        }
        return true;
    };
    double lo = 0, hi = spec_.volume_mm3;
    while (!close(hi))
        hi *= 2;
    while (hi - lo > 0.01) {
        const double mid = (lo + hi) / 2;
        (close(mid) ? hi : lo) = mid;
    }
    return hi;
}

double fullChangeVolumeMm3(const ChamberSpec& spec, double tolerance) {
    Chamber chamber(spec, MixVector::only(0, 2));
    return chamber.volumeToReach(MixVector::only(1, 2), tolerance);
}

}  // namespace mixengine
