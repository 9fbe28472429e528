#include "mixing/transition/LeadCommands.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace mixengine {
namespace {

/// One cell's push as a linear map, per channel, on the deviations d = tank − command:
///   tank_j after  = command + Σ_{m ≤ min(j, reach)} w_m d_{j−m}
///   outlet (avg)  = command + Σ_{i ≤ reach} g_i d_{N−1−i}
/// (w the Poisson weights, g_i = P(i + 1, τ) / τ; mixing/chamber/ChamberModel.h has the closed form).
struct PushMap {
    std::size_t first = 0;  ///< offset of its weights in ChamberOperator's arrays
    int reach = 0;          ///< weights beyond are 0
};

class ChamberOperator {
  public:
    ChamberOperator(const std::vector<FlowCell>& cells, const ChamberSpec& spec, int channels)
        : stages_(std::max(1, spec.stages)), channels_(channels) {
        maps_.reserve(cells.size());
        for (const FlowCell& cell : cells)
            addPush(spec.ideal() ? 1e6 : cell.volume_mm3 * stages_ / spec.volume_mm3);
    }

    /// Outlets (cells × channels, flat) of `commands` (the same shape) from `tanks` (stages × channels).
    std::vector<double> forward(const std::vector<double>& commands, std::vector<double> tanks) const {
        std::vector<double> out(commands.size(), 0.0);
        const auto n = static_cast<std::size_t>(stages_);
        for (std::size_t k = 0; k < maps_.size(); ++k) {
            const PushMap& p = maps_[k];
            for (std::size_t c = 0; c < static_cast<std::size_t>(channels_); ++c) {
                const double cmd = commands[k * ch() + c];
                double left = cmd;
                for (int i = 0; i <= p.reach; ++i)
                    left += g_[p.first + static_cast<std::size_t>(i)] * (tanks[(n - 1 - i) * ch() + c] - cmd);
                out[k * ch() + c] = left;
                for (std::size_t j = n; j-- > 0;) {
                    double next = cmd;
                    const std::size_t top = std::min<std::size_t>(j, static_cast<std::size_t>(p.reach));
                    for (std::size_t m = 0; m <= top; ++m)
                        next += w_[p.first + m] * (tanks[(j - m) * ch() + c] - cmd);
                    tanks[j * ch() + c] = next;
                }
            }
        }
        return out;
    }

    /// The gradient with respect to the commands of Σ errors · outlets (the adjoint of forward).
    std::vector<double> adjoint(const std::vector<double>& errors) const {
        std::vector<double> grad(errors.size(), 0.0);
        const auto n = static_cast<std::size_t>(stages_);
        std::vector<double> lambda(n * ch(), 0.0);  // ∂/∂ tanks after the cell
        for (std::size_t k = maps_.size(); k-- > 0;) {
            const PushMap& p = maps_[k];
            const auto reach = static_cast<std::size_t>(p.reach);
            for (std::size_t c = 0; c < ch(); ++c) {
                const double e = errors[k * ch() + c];
                double g = (1.0 - gSum_[k]) * e;
                for (std::size_t j = 0; j < n; ++j)
                    g += (1.0 - wCum_[p.first + std::min(j, reach)]) * lambda[j * ch() + c];
                grad[k * ch() + c] = g;
                for (std::size_t j = 0; j < n; ++j) {  // ascending: λ[j + m], m > 0, still the old values
                    double before = 0;
                    const std::size_t top = std::min(n - 1 - j, reach);
                    for (std::size_t m = 0; m <= top; ++m)
                        before += w_[p.first + m] * lambda[(j + m) * ch() + c];
                    if (n - 1 - j <= reach)
                        before += g_[p.first + (n - 1 - j)] * e;
                    lambda[j * ch() + c] = before;
                }
            }
        }
        return grad;
    }

  private:
    int stages_, channels_;
    std::vector<PushMap> maps_;
    std::vector<double> w_, wCum_, g_;  ///< per cell, reach + 1 entries from PushMap::first
    std::vector<double> gSum_;          ///< per cell

    std::size_t ch() const { return static_cast<std::size_t>(channels_); }

    void addPush(double tau) {
        const std::vector<double> w = poissonWeights(tau, stages_);
        const std::vector<double> p = gammaP(w);
        int reach = stages_ - 1;
        for (int i = static_cast<int>(tau) + 1; i < stages_; ++i)
            if (w[static_cast<std::size_t>(i)] < 1e-17) {
                reach = i;
                break;
            }
        maps_.push_back({w_.size(), reach});
        double cum = 0, gsum = 0;
        for (int i = 0; i <= reach; ++i) {
            const auto u = static_cast<std::size_t>(i);
            cum += w[u];
            w_.push_back(w[u]);
            wCum_.push_back(cum);
            const double g = tau > 0 ? p[u] / tau : (i == 0 ? 1.0 : 0.0);
            g_.push_back(g);
            gsum += g;
        }
        gSum_.push_back(gsum);
    }
};

/// Euclidean projection of `v` (n values) onto the simplex Σ = 1, all ≥ 0.
void projectToSimplex(double* v, int n) {
    double sorted[kMaxMixChannels] = {};
    const int count = std::clamp(n, 1, kMaxMixChannels);
    for (int i = 0; i < count; ++i) {  // insertion sort, largest first
        int j = i;
        for (; j > 0 && sorted[j - 1] < v[i]; --j)
            sorted[j] = sorted[j - 1];
        sorted[j] = v[i];
    }
    double cum = 0, theta = 0;
    for (int i = 0; i < count; ++i) {
        cum += sorted[i];
        const double t = (cum - 1.0) / (i + 1);
        if (sorted[i] - t > 0)
            theta = t;
    }
    for (int i = 0; i < count; ++i)
        v[i] = std::max(0.0, v[i] - theta);
}

std::vector<double> flatten(const std::vector<MixVector>& mixes, int channels) {
    std::vector<double> out;
    out.reserve(mixes.size() * static_cast<std::size_t>(channels));
    for (const MixVector& m : mixes)
        for (int c = 0; c < channels; ++c)
            out.push_back(m[c]);
    return out;
}

std::vector<MixVector> unflatten(const std::vector<double>& flat, int channels) {
    std::vector<MixVector> out(flat.size() / static_cast<std::size_t>(channels));
    for (std::size_t k = 0; k < out.size(); ++k) {
        out[k].channels = channels;
        for (int c = 0; c < channels; ++c)
            out[k][c] = flat[k * static_cast<std::size_t>(channels) + static_cast<std::size_t>(c)];
    }
    return out;
}

/// The problem in flat arrays: weights normalised to a mean of 1 over the asked cells.
struct Problem {
    const ChamberOperator& chamber;
    std::vector<double> tanks, asked, weight, margin;  ///< margin: per cell
    int channels;

    /// ∂ loss / ∂ outlet for every cell and channel.
    std::vector<double> errors(const std::vector<double>& outlets) const {
        std::vector<double> e(outlets.size(), 0.0);
        for (std::size_t i = 0; i < e.size(); ++i) {
            const std::size_t cell = i / static_cast<std::size_t>(channels);
            if (weight[cell] <= 0)
                continue;
            const double w = weight[cell];
            const double d = outlets[i] - asked[i];
            const double over = std::abs(d) - margin[cell];
            if (over > 0)
                e[i] = 2.0 * w * (d > 0 ? over : -over);
        }
        return e;
    }
};

/// The largest eigenvalue of 2 Jᵀ W J (J: commands → outlets, W: the weights), by power iteration —
/// the gradient's Lipschitz constant, so 1 / it is a safe step.
double lipschitz(const Problem& problem, std::size_t size) {
    std::vector<double> v(size, 1.0);
    const std::vector<double> empty(problem.tanks.size(), 0.0);
    double norm = 1.0;
    for (int round = 0; round < 20; ++round) {
        std::vector<double> jv = problem.chamber.forward(v, empty);
        for (std::size_t i = 0; i < jv.size(); ++i)
            jv[i] *= 2.0 * problem.weight[i / static_cast<std::size_t>(problem.channels)];
        v = problem.chamber.adjoint(jv);
        norm = 0;
        for (double x : v)
            norm = std::max(norm, std::abs(x));
        if (norm <= 0)
            return 1.0;
        for (double& x : v)
            x /= norm;
    }
    return norm * 1.2;
}

}  // namespace

std::vector<MixVector> outletsOf(const std::vector<FlowCell>& cells, const std::vector<MixVector>& tanks,
                                 const std::vector<MixVector>& commands, const ChamberSpec& chamber) {
    const int channels = tanks.empty() ? 1 : tanks.front().channels;
    const ChamberOperator op(cells, chamber, channels);
    return unflatten(op.forward(flatten(commands, channels), flatten(tanks, channels)), channels);
}

std::vector<MixVector> leadCommands(const std::vector<FlowCell>& cells, const std::vector<MixVector>& tanks,
                                    std::vector<MixVector> start, const LeadSettings& settings) {
    if (cells.empty() || tanks.empty() || settings.chamber.ideal())
        return start;
    const int channels = tanks.front().channels;
    const ChamberOperator op(cells, settings.chamber, channels);
    Problem problem{op, flatten(tanks, channels), {}, {}, {}, channels};
    double total = 0;
    int asked = 0;
    for (const FlowCell& cell : cells) {
        problem.weight.push_back(cell.weight);
        problem.margin.push_back(cell.margin >= 0 ? cell.margin : settings.margin);
        total += cell.weight;
        asked += cell.weight > 0 ? 1 : 0;
        for (int c = 0; c < channels; ++c)
            problem.asked.push_back(cell.asked[c]);
    }
    if (asked == 0)
        return start;
    for (double& w : problem.weight)
        w *= asked / total;
    const double step = 1.0 / lipschitz(problem, cells.size() * static_cast<std::size_t>(channels));
    std::vector<double> x = flatten(start, channels), y = x;
    double t = 1.0;
    for (int it = 0; it < settings.iterations; ++it) {
        const std::vector<double> grad = op.adjoint(problem.errors(op.forward(y, problem.tanks)));
        std::vector<double> next(y.size());
        for (std::size_t i = 0; i < y.size(); ++i)
            next[i] = y[i] - step * grad[i];
        for (std::size_t k = 0; k < cells.size(); ++k)
            projectToSimplex(&next[k * static_cast<std::size_t>(channels)], channels);
        const double t_next = (1.0 + std::sqrt(1.0 + 4.0 * t * t)) / 2.0;
        for (std::size_t i = 0; i < y.size(); ++i)
            y[i] = next[i] + (t - 1.0) / t_next * (next[i] - x[i]);
        x = std::move(next);
        t = t_next;
    }
    return unflatten(x, channels);
}

std::vector<MixVector> leadingGuess(const std::vector<FlowCell>& cells, double lead_mm3,
                                    const MixVector& fallback) {
    std::vector<double> start_mm3;  // where each cell begins along the flow
    std::vector<std::size_t> asked;
    double flow = 0;
    for (std::size_t k = 0; k < cells.size(); ++k) {
        start_mm3.push_back(flow);
        if (cells[k].weight > 0)
            asked.push_back(k);
        flow += cells[k].volume_mm3;
    }
    std::vector<MixVector> guess(cells.size(), fallback);
    if (asked.empty())
        return guess;
    std::size_t next = 0;  // the first asked cell that begins at or after the point looked at
    for (std::size_t k = 0; k < cells.size(); ++k) {
        const double point = start_mm3[k] + cells[k].volume_mm3 / 2 + lead_mm3;
        while (next < asked.size() && start_mm3[asked[next]] + cells[asked[next]].volume_mm3 < point)
            ++next;
        guess[k] = cells[asked[std::min(next, asked.size() - 1)]].asked;
    }
    return guess;
}

}  // namespace mixengine
