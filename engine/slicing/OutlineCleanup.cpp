#include "slicing/OutlineCleanup.h"

#include <algorithm>
#include <cmath>

#include "common/ParallelFor.h"

namespace mixengine {
namespace {

constexpr double kCollinearUm = 5.0;

double lengthUm(const Point2& a, const Point2& b) {
    return std::hypot(static_cast<double>(b.X - a.X), static_cast<double>(b.Y - a.Y));
}

/// Distance from p to the segment a–b.
double deviationUm(const Point2& p, const Point2& a, const Point2& b) {
    const double dx = double(b.X - a.X), dy = double(b.Y - a.Y);
    const double length_sq = dx * dx + dy * dy;
    double t = length_sq > 0 ? (double(p.X - a.X) * dx + double(p.Y - a.Y) * dy) / length_sq : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    return std::hypot(double(a.X) + t * dx - double(p.X), double(a.Y) + t * dy - double(p.Y));
}

bool allWithin(const Path& dropped, const Point2& a, const Point2& b, double limit) {
    return std::all_of(dropped.begin(), dropped.end(),
                       [&](const Point2& p) { return deviationUm(p, a, b) <= limit; });
}

}  // namespace

double loopLengthUm(const Path& loop) {
    double sum = 0;
    for (std::size_t i = 0; i < loop.size(); ++i)
        sum += lengthUm(loop[i], loop[(i + 1) % loop.size()]);
    return sum;
}

Path simplifyLoop(const Path& loop, coord_um maximum_resolution_um, coord_um maximum_deviation_um) {
    const std::size_t n = loop.size();
    if (n <= 3)
        return loop;
    Path kept{loop.front()};
    Path dropped;
    for (std::size_t i = 1; i < n; ++i) {
        const Point2& candidate = loop[i];
        const Point2& next = loop[(i + 1) % n];
        dropped.push_back(candidate);
        const bool collinear = allWithin(dropped, kept.back(), next, kCollinearUm);
        const bool fine = lengthUm(kept.back(), candidate) < double(maximum_resolution_um) &&
                          allWithin(dropped, kept.back(), next, double(maximum_deviation_um));
        if (collinear || fine)
            continue;
        kept.push_back(candidate);
        dropped.clear();
    }
    if (kept.size() < 3)
        return loop;
    return kept;
}

void cleanOutlines(std::vector<SlicedLayer>& layers, const OutlineCleanupParams& params, int threads) {
    parallelFor(layers.size(), threads, [&](std::size_t i) {
        Paths& outlines = layers[i].outlines;
        std::erase_if(outlines, [&](const Path& p) {
            return loopLengthUm(p) < double(params.minimum_circumference_um);
        });
        if (params.maximum_resolution_um <= 0 && params.maximum_deviation_um <= 0)
            return;
        for (Path& loop : outlines)
            loop = simplifyLoop(loop, params.maximum_resolution_um, params.maximum_deviation_um);
    });
}

void removeHoles(std::vector<SlicedLayer>& layers, int threads) {
    parallelFor(layers.size(), threads, [&](std::size_t i) {
        Paths& outlines = layers[i].outlines;
        std::erase_if(outlines, [](const Path& loop) { return !ClipperLib::Orientation(loop); });
        ClipperLib::Clipper clipper;
        clipper.AddPaths(outlines, ClipperLib::ptSubject, true);
        Paths united;
        clipper.Execute(ClipperLib::ctUnion, united, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
        outlines = std::move(united);
    });
}

}  // namespace mixengine
