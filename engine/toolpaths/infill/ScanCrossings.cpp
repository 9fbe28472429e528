#include "toolpaths/infill/ScanCrossings.h"

#include <algorithm>
#include <cmath>

#include "toolpaths/infill/LineFrame.h"

namespace mixengine {
namespace {

/// The crossings of the edge a → b with the scanlines, in walking order.
void appendEdgeCrossings(const Point2& a, const Point2& b, coord_um d, coord_um phase, ScanCrossing base,
                         std::vector<ScanCrossing>& out) {
    if (a.X == b.X)
        return;
    // Scanlines k with a side change: x_k in (min, max] for the "x >= x_k is right" rule.
    const long long lo = floorDiv(std::min(a.X, b.X) - phase, d) + 1;
    const long long hi = floorDiv(std::max(a.X, b.X) - phase, d);
    const std::size_t first = out.size();
    for (long long k = lo; k <= hi; ++k) {
        const double x = double(phase) + double(k) * double(d);
        const double t = (x - double(a.X)) / double(b.X - a.X);
        base.line = k;
        base.point = {static_cast<coord_um>(x), std::llround(double(a.Y) + t * double(b.Y - a.Y))};
        base.along = t;
        out.push_back(base);
    }
    if (a.X > b.X)
        std::reverse(out.begin() + static_cast<std::ptrdiff_t>(first), out.end());
}

}  // namespace

std::vector<ScanCrossing> findScanCrossings(const Paths& polys, coord_um d, coord_um phase) {
    std::vector<ScanCrossing> out;
    if (d <= 0)
        return out;
    for (std::size_t pi = 0; pi < polys.size(); ++pi) {
        const Path& poly = polys[pi];
        for (std::size_t e = 0; e < poly.size(); ++e) {
            ScanCrossing base;
            base.polygon = pi;
            base.edge = e;
            appendEdgeCrossings(poly[e], poly[(e + 1) % poly.size()], d, phase, base, out);
        }
    }
    return out;
}

std::vector<long> pairOnScanlines(const std::vector<ScanCrossing>& cs) {
    std::vector<long> partner(cs.size(), -1);
    std::vector<long> order(cs.size());
    for (std::size_t i = 0; i < cs.size(); ++i)
        order[i] = static_cast<long>(i);
    std::sort(order.begin(), order.end(), [&](long a, long b) {
        const ScanCrossing &ca = cs[std::size_t(a)], &cb = cs[std::size_t(b)];
        return ca.line != cb.line ? ca.line < cb.line : ca.point.Y < cb.point.Y;
    });
    for (std::size_t i = 0; i + 1 < order.size(); i += 2) {
        if (cs[std::size_t(order[i])].line != cs[std::size_t(order[i + 1])].line) {
            --i;  // an odd crossing count on a line (degenerate): resynchronise
            continue;
        }
        partner[std::size_t(order[i])] = order[i + 1];
        partner[std::size_t(order[i + 1])] = order[i];
    }
    return partner;
}

}  // namespace mixengine
