#include "orient/VoxelGrid.h"

#include <algorithm>
#include <cmath>

#include "common/ParallelFor.h"

namespace mixengine::orient {
namespace {

/// A facet projected on the xy-plane, reordered counter-clockwise; `sign` +1 when a ray going up
/// enters the solid through it (down-facing facet), −1 when it leaves.
struct Facet {
    Point3 a, b, c;
    int sign = 0;
    coord_um min_x = 0, max_x = 0, min_y = 0, max_y = 0;
};

/// Twice the signed area of (a, b, p) in µm²; exact (coordinates within ±1 km fit in int64).
std::int64_t edgeFunction(const Point3& a, const Point3& b, coord_um px, coord_um py) {
    return (b.x - a.x) * (py - a.y) - (b.y - a.y) * (px - a.x);
}

/// Top-left rule: an edge of a CCW triangle owns the points on it when it goes down, or goes
/// left horizontally. The reverse edge of a neighbour then does not, so each point counts once.
bool ownsEdgePoints(const Point3& a, const Point3& b) {
    return b.y < a.y || (b.y == a.y && b.x < a.x);
}

bool covers(const Point3& a, const Point3& b, std::int64_t e) {
    return e > 0 || (e == 0 && ownsEdgePoints(a, b));
}

std::vector<Facet> projectFacets(const Mesh& mesh) {
    std::vector<Facet> facets;
    facets.reserve(mesh.faces.size());
    for (const Face& face : mesh.faces) {
        Facet f{mesh.vertices[face.v[0]], mesh.vertices[face.v[1]], mesh.vertices[face.v[2]]};
        const std::int64_t area2 = edgeFunction(f.a, f.b, f.c.x, f.c.y);
        if (area2 == 0)
            continue;  // vertical facet: no ray crosses it
        f.sign = area2 > 0 ? -1 : 1;
        if (area2 < 0)
            std::swap(f.b, f.c);
        f.min_x = std::min({f.a.x, f.b.x, f.c.x});
        f.max_x = std::max({f.a.x, f.b.x, f.c.x});
        f.min_y = std::min({f.a.y, f.b.y, f.c.y});
        f.max_y = std::max({f.a.y, f.b.y, f.c.y});
        facets.push_back(f);
    }
    return facets;
}

/// Ray positions (µm) of the sub-samples along one axis: (cell + (s + 0.5) / samples) * step.
std::vector<coord_um> rayPositions(double origin_mm, double step_mm, int cells, int samples) {
    std::vector<coord_um> pos(static_cast<std::size_t>(cells) * samples);
    for (std::size_t t = 0; t < pos.size(); ++t) {
        pos[t] = mmToMicrons(origin_mm + (static_cast<double>(t) + 0.5) / samples * step_mm);
    }
    return pos;
}

/// Index range [first, last) of the sorted `pos` within [lo, hi].
std::pair<std::size_t, std::size_t> rangeWithin(const std::vector<coord_um>& pos, coord_um lo, coord_um hi) {
    const auto first = std::lower_bound(pos.begin(), pos.end(), lo);
    const auto last = std::upper_bound(first, pos.end(), hi);
    return {static_cast<std::size_t>(first - pos.begin()), static_cast<std::size_t>(last - pos.begin())};
}

struct Hit {
    double z_mm;
    int sign;
    bool operator<(const Hit& o) const { return z_mm < o.z_mm; }
};

/// Inside intervals along one ray within [z_lo, z_hi]; false when the crossings do not close. Then
/// the facets' orientation alone decides: inside from an entering crossing to the next leaving one,
/// from z_lo when the first crossing leaves, up to z_hi when the last one enters (so a missing
/// facet — a hole — is bridged by the part's extent along the ray).
bool insideIntervals(std::vector<Hit>& hits, double z_lo, double z_hi,
                     std::vector<std::pair<double, double>>& out) {
    out.clear();
    std::sort(hits.begin(), hits.end());
    int total = 0;
    for (const Hit& h : hits)
        total += h.sign;
    if (total != 0) {
        bool inside = hits.front().sign < 0;
        double start = z_lo;
        for (const Hit& h : hits) {
            if (h.sign > 0 && !inside) {
                inside = true;
                start = h.z_mm;
            } else if (h.sign < 0 && inside) {
                out.emplace_back(start, h.z_mm);
                inside = false;
            }
        }
        if (inside)
            out.emplace_back(start, z_hi);
        return false;
    }
    int winding = 0;
    for (std::size_t i = 0; i + 1 < hits.size(); ++i) {
        winding += hits[i].sign;
        if (winding != 0 && hits[i + 1].z_mm > hits[i].z_mm)
            out.emplace_back(hits[i].z_mm, hits[i + 1].z_mm);
    }
    return true;
}

/// Adds the covered length of [z0, z1] to the cells of one column, scaled by `weight`.
void addInterval(float* column, const GridFrame& frame, double z0, double z1, double weight) {
    const double h = frame.step_mm[2];
    const double t0 = (z0 - frame.origin_mm.z) / h, t1 = (z1 - frame.origin_mm.z) / h;
    const int k0 = std::max(0, static_cast<int>(std::floor(t0)));
    const int k1 = std::min(frame.cells[2] - 1, static_cast<int>(std::floor(t1)));
    for (int k = k0; k <= k1; ++k) {
        const double covered = std::min(t1, k + 1.0) - std::max(t0, static_cast<double>(k));
        if (covered > 0)
            column[k] += static_cast<float>(covered * weight);
    }
}

double zOnFacet(const Facet& f, std::int64_t wa, std::int64_t wb, std::int64_t wc) {
    const double sum = static_cast<double>(wa) + static_cast<double>(wb) + static_cast<double>(wc);
    const double z_um = (static_cast<double>(wa) * static_cast<double>(f.a.z) +
                         static_cast<double>(wb) * static_cast<double>(f.b.z) +
                         static_cast<double>(wc) * static_cast<double>(f.c.z)) /
                        sum;
    return z_um / kMicronsPerMm;
}

}  // namespace

GridFrame frameCovering(const Vec3& min_mm, const Vec3& max_mm, int resolution) {
    GridFrame frame;
    frame.origin_mm = min_mm;
    const double extent[3] = {max_mm.x - min_mm.x, max_mm.y - min_mm.y, max_mm.z - min_mm.z};
    const double longest = std::max({extent[0], extent[1], extent[2]});
    const double target = longest / std::max(1, resolution);
    for (int a = 0; a < 3; ++a) {
        if (extent[a] <= 0 || target <= 0) {
            frame.cells[a] = 1;
            frame.step_mm[a] = std::max(target, 1e-3);
            continue;
        }
        frame.cells[a] = std::max(1, static_cast<int>(std::lround(extent[a] / target)));
        frame.step_mm[a] = extent[a] / frame.cells[a];
    }
    return frame;
}

std::pair<Vec3, Vec3> boundsMm(const Mesh& mesh) {
    const AABB3 box = mesh.bounds();
    return {{micronsToMm(box.min.x), micronsToMm(box.min.y), micronsToMm(box.min.z)},
            {micronsToMm(box.max.x), micronsToMm(box.max.y), micronsToMm(box.max.z)}};
}

double VoxelGrid::volumeMm3() const {
    double sum = 0;
    for (const float f : fraction)
        sum += f;
    return sum * frame.cellVolumeMm3();
}

VoxelGrid voxelise(const Mesh& mesh, const GridFrame& frame, int samples, int threads) {
    const int s = std::max(1, samples);
    VoxelGrid grid;
    grid.frame = frame;
    grid.fraction.assign(frame.cellCount(), 0.0f);
    const std::vector<Facet> facets = projectFacets(mesh);
    const std::vector<coord_um> xs = rayPositions(frame.origin_mm.x, frame.step_mm[0], frame.cells[0], s);
    const std::vector<coord_um> ys = rayPositions(frame.origin_mm.y, frame.step_mm[1], frame.cells[1], s);
    std::vector<std::vector<std::uint32_t>> rows(static_cast<std::size_t>(frame.cells[0]));
    for (std::size_t n = 0; n < facets.size(); ++n) {
        const auto [first, last] = rangeWithin(xs, facets[n].min_x, facets[n].max_x);
        for (std::size_t row = first / s; row * s < last; ++row)
            rows[row].push_back(static_cast<std::uint32_t>(n));
    }
    std::vector<std::size_t> inconsistent(rows.size(), 0);
    const double weight = 1.0 / (s * s);
    parallelFor(rows.size(), threads, [&](std::size_t row) {
        const std::size_t per_x = ys.size();
        std::vector<std::vector<Hit>> hits(static_cast<std::size_t>(s) * per_x);
        for (const std::uint32_t n : rows[row]) {
            const Facet& f = facets[n];
            const auto [y0, y1] = rangeWithin(ys, f.min_y, f.max_y);
            for (int sx = 0; sx < s; ++sx) {
                const coord_um px = xs[row * s + sx];
                if (px < f.min_x || px > f.max_x)
                    continue;
                for (std::size_t t = y0; t < y1; ++t) {
                    const std::int64_t wa = edgeFunction(f.b, f.c, px, ys[t]);
                    const std::int64_t wb = edgeFunction(f.c, f.a, px, ys[t]);
                    const std::int64_t wc = edgeFunction(f.a, f.b, px, ys[t]);
                    if (covers(f.b, f.c, wa) && covers(f.c, f.a, wb) && covers(f.a, f.b, wc))
                        hits[sx * per_x + t].push_back({zOnFacet(f, wa, wb, wc), f.sign});
                }
            }
        }
        std::vector<std::pair<double, double>> intervals;
        const double z_lo = frame.origin_mm.z, z_hi = frame.origin_mm.z + frame.cells[2] * frame.step_mm[2];
        for (std::size_t r = 0; r < hits.size(); ++r) {
            if (hits[r].empty())
                continue;
            if (!insideIntervals(hits[r], z_lo, z_hi, intervals))
                ++inconsistent[row];
            const std::size_t j = (r % per_x) / s;
            float* column = &grid.fraction[(row * frame.cells[1] + j) * frame.cells[2]];
            for (const auto& [z0, z1] : intervals)
                addInterval(column, frame, z0, z1, weight);
        }
    });
    grid.rays = xs.size() * ys.size();
    for (const std::size_t n : inconsistent)
        grid.inconsistent_rays += n;
    return grid;
}

}  // namespace mixengine::orient
