#include "toolpaths/core/LayerWindows.h"

#include <algorithm>

#include "common/ParallelFor.h"
#include "geometry/PolygonOps.h"

namespace mixengine {
namespace {

/// The windows by doubling, for a window of 2^k layers: the combinations of 2, 4, … consecutive
/// layers, each from two of the level below — k operations per layer (2 for the usual 4 layers,
/// where the block scheme needs 2.5).
template <typename Op>
std::vector<Paths> doubledWindows(const std::vector<Paths>& layers, std::size_t w, int threads, Op op) {
    const std::size_t n = layers.size();
    std::vector<Paths> level;
    const std::vector<Paths>* below = &layers;  // the level below: the layers themselves at first, no copy
    for (std::size_t span = 1; span < w; span *= 2) {
        std::vector<Paths> next(n);
        parallelFor(n, threads, [&](std::size_t i) {
            if (i + 2 * span <= n)
                next[i] = op((*below)[i], (*below)[i + span]);
        });
        level = std::move(next);
        below = &level;
    }
    return level;
}

template <typename Op>
std::vector<Paths> windowCombine(const std::vector<Paths>& layers, int window, int threads, Op op) {
    const std::size_t n = layers.size();
    std::vector<Paths> result(n);
    if (window <= 1) {
        if (window == 1)
            result = layers;
        return result;
    }
    const std::size_t w = static_cast<std::size_t>(window);
    if ((w & (w - 1)) == 0)
        return doubledWindows(layers, w, threads, op);
    std::vector<Paths> prefix(n), suffix(n);
    parallelFor((n + w - 1) / w, threads, [&](std::size_t b) {
        const std::size_t begin = b * w, end = std::min(n, begin + w);
        prefix[begin] = layers[begin];
        for (std::size_t j = begin + 1; j < end; ++j)
            prefix[j] = op(prefix[j - 1], layers[j]);
        suffix[end - 1] = layers[end - 1];
        for (std::size_t j = end - 1; j-- > begin;)
            suffix[j] = op(layers[j], suffix[j + 1]);
    });
    parallelFor(n, threads, [&](std::size_t s) {
        const std::size_t e = s + w - 1;
        if (e < n)
            result[s] = s % w == 0 ? suffix[s] : op(suffix[s], prefix[e]);
    });
    return result;
}

}  // namespace

std::vector<Paths> windowIntersections(const std::vector<Paths>& layers, int window, int threads) {
    return windowCombine(layers, window, threads,
                         [](const Paths& a, const Paths& b) { return intersectAll(a, b); });
}

std::vector<Paths> windowUnions(const std::vector<Paths>& layers, int window, int threads) {
    return windowCombine(layers, window, threads,
                         [](const Paths& a, const Paths& b) { return unionOf(a, b); });
}

}  // namespace mixengine
