#include "mixing/fields/PaintedRegions.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mixengine {
namespace {

constexpr int kMaxCellsPerAxis = 96;

void sub(const double x[3], const double y[3], double out[3]) {
    for (int k = 0; k < 3; ++k)
        out[k] = x[k] - y[k];
}

double dot(const double x[3], const double y[3]) {
    return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
}

double squaredTo(const double p[3], const double q[3]) {
    double d[3];
    sub(p, q, d);
    return dot(d, d);
}

/// Squared distance from p to the point q = o + s·u + t·v (written to q).
double squaredToPoint(const double p[3], const double o[3], const double u[3], const double v[3], double s,
                      double t, double q[3]) {
    for (int k = 0; k < 3; ++k)
        q[k] = o[k] + s * u[k] + t * v[k];
    return squaredTo(p, q);
}

/// Squared distance from p to the segment from o to o + u; its nearest point to q.
double squaredToSegment(const double p[3], const double o[3], const double u[3], double q[3]) {
    double w[3];
    sub(p, o, w);
    const double uu = dot(u, u);
    const double s = uu > 0 ? std::clamp(dot(w, u) / uu, 0.0, 1.0) : 0.0;
    const double zero[3] = {0, 0, 0};
    return squaredToPoint(p, o, u, zero, s, 0, q);
}

}  // namespace

double squaredDistanceToTriangle(const double p[3], const double a[3], const double b[3], const double c[3],
                                 double nearest[3]) {
    double u[3], v[3], w[3];
    sub(b, a, u);
    sub(c, a, v);
    sub(p, a, w);
    // The foot of the perpendicular in barycentric terms: solve [uu uv; uv vv] (s, t) = (wu, wv).
    const double uu = dot(u, u), uv = dot(u, v), vv = dot(v, v), wu = dot(w, u), wv = dot(w, v);
    const double det = uu * vv - uv * uv;
    if (det > 0) {
        const double s = (vv * wu - uv * wv) / det;
        const double t = (uu * wv - uv * wu) / det;
        if (s >= 0 && t >= 0 && s + t <= 1)
            return squaredToPoint(p, a, u, v, s, t, nearest);
    }
    // Outside (or degenerate): the nearest point lies on an edge; the first of equally near edges wins.
    double bc[3], q[3][3];
    sub(c, b, bc);
    const double d[3] = {squaredToSegment(p, a, u, q[0]), squaredToSegment(p, a, v, q[1]),
                         squaredToSegment(p, b, bc, q[2])};
    const int k = d[1] < d[0] ? (d[2] < d[1] ? 2 : 1) : (d[2] < d[0] ? 2 : 0);
    for (int i = 0; i < 3; ++i)
        nearest[i] = q[k][i];
    return d[k];
}

double squaredDistanceToTriangle(const double p[3], const double a[3], const double b[3], const double c[3]) {
    double nearest[3];
    return squaredDistanceToTriangle(p, a, b, c, nearest);
}

PaintedRegions::PaintedRegions(const Mesh& mesh, std::vector<int> face_region, coord_um depth_um,
                               coord_um extra_reach_um)
    : region_(std::move(face_region)),
      depth_um_(static_cast<double>(depth_um)),
      reach_um_(static_cast<double>(depth_um + std::max<coord_um>(0, extra_reach_um))) {
    for (const int r : region_)
        region_count_ = std::max(region_count_, r + 1);
    double lo[3] = {std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
                    std::numeric_limits<double>::max()};
    double hi[3] = {std::numeric_limits<double>::lowest(), std::numeric_limits<double>::lowest(),
                    std::numeric_limits<double>::lowest()};
    for (const Face& f : mesh.faces) {
        Triangle t{};
        double* corners[3] = {t.a, t.b, t.c};
        for (int k = 0; k < 3; ++k) {
            const Point3& p = mesh.vertices[f.v[static_cast<std::size_t>(k)]];
            const double xyz[3] = {static_cast<double>(p.x), static_cast<double>(p.y),
                                   static_cast<double>(p.z)};
            for (int d = 0; d < 3; ++d) {
                corners[k][d] = xyz[d];
                lo[d] = std::min(lo[d], xyz[d] - depth_um_);
                hi[d] = std::max(hi[d], xyz[d] + depth_um_);
            }
        }
        for (int d = 0; d < 3; ++d) {
            t.lo[d] = std::min({t.a[d], t.b[d], t.c[d]});
            t.hi[d] = std::max({t.a[d], t.b[d], t.c[d]});
        }
        triangles_.push_back(t);
    }
    if (triangles_.empty())
        return;
    const double extent = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
    cell_um_ = std::max({depth_um_, extent / kMaxCellsPerAxis, 1.0});
    for (int d = 0; d < 3; ++d) {
        origin_[d] = lo[d];
        dims_[d] = std::max(1, static_cast<int>(std::ceil((hi[d] - lo[d]) / cell_um_)));
    }
    fillGrid();
    buildTrees();
}

void PaintedRegions::buildTrees() {
    std::vector<std::vector<TriangleTree::Corners>> corners(static_cast<std::size_t>(region_count_));
    region_faces_.assign(static_cast<std::size_t>(region_count_), {});
    for (std::size_t f = 0; f < triangles_.size(); ++f) {
        if (region_[f] < 0)
            continue;
        const Triangle& t = triangles_[f];
        corners[static_cast<std::size_t>(region_[f])].push_back(
            {t.a[0], t.a[1], t.a[2], t.b[0], t.b[1], t.b[2], t.c[0], t.c[1], t.c[2]});
        region_faces_[static_cast<std::size_t>(region_[f])].push_back(static_cast<int>(f));
    }
    for (std::vector<TriangleTree::Corners>& region : corners)
        region_trees_.emplace_back(std::move(region));
}

NearestPaint PaintedRegions::nearestOf(int region, const double p[3], double limit_sq) const {
    NearestPaint nearest;
    if (region < 0 || region >= static_cast<int>(region_trees_.size()))
        return nearest;
    const TriangleTree& tree = region_trees_[static_cast<std::size_t>(region)];
    const auto [d, index] = tree.nearest(p, limit_sq);
    if (index < 0)
        return nearest;
    const TriangleTree::Corners& t = tree.triangle(index);
    nearest.region = region;
    nearest.distance_um =
        std::sqrt(squaredDistanceToTriangle(p, &t[0], &t[3], &t[6], nearest.point_um.data()));
    return nearest;
}

void PaintedRegions::fillGrid() {
    const std::size_t cells = static_cast<std::size_t>(dims_[0]) * static_cast<std::size_t>(dims_[1]) *
                              static_cast<std::size_t>(dims_[2]);
    std::vector<std::uint32_t> count(cells + 1, 0);
    // Two passes over the triangles' depth-expanded boxes: count per cell, then fill (CSR layout).
    for (int pass = 0; pass < 2; ++pass) {
        for (std::size_t i = 0; i < triangles_.size(); ++i) {
            const Triangle& t = triangles_[i];
            double box_lo[3], box_hi[3];
            for (int d = 0; d < 3; ++d) {
                box_lo[d] = std::min({t.a[d], t.b[d], t.c[d]}) - depth_um_;
                box_hi[d] = std::max({t.a[d], t.b[d], t.c[d]}) + depth_um_;
            }
            int first[3], last[3];
            cellRange(box_lo, box_hi, first, last);
            for (int x = first[0]; x <= last[0]; ++x)
                for (int y = first[1]; y <= last[1]; ++y)
                    for (int z = first[2]; z <= last[2]; ++z) {
                        const std::size_t cell = cellIndex(x, y, z);
                        if (pass == 0)
                            ++count[cell + 1];
                        else
                            cell_items_[count[cell]++] = static_cast<std::uint32_t>(i);
                    }
        }
        if (pass == 0) {
            for (std::size_t c = 1; c <= cells; ++c)
                count[c] += count[c - 1];
            cell_start_ = count;
            cell_items_.resize(count[cells]);
        }
    }
}

bool PaintedRegions::cellRange(const double lo[3], const double hi[3], int first[3], int last[3]) const {
    bool inside = true;
    for (int d = 0; d < 3; ++d) {
        first[d] = static_cast<int>(std::floor((lo[d] - origin_[d]) / cell_um_));
        last[d] = static_cast<int>(std::floor((hi[d] - origin_[d]) / cell_um_));
        inside = inside && last[d] >= 0 && first[d] < dims_[d];
        first[d] = std::clamp(first[d], 0, dims_[d] - 1);
        last[d] = std::clamp(last[d], 0, dims_[d] - 1);
    }
    return inside;
}

std::size_t PaintedRegions::cellIndex(int x, int y, int z) const {
    return (static_cast<std::size_t>(z) * static_cast<std::size_t>(dims_[1]) + static_cast<std::size_t>(y)) *
               static_cast<std::size_t>(dims_[0]) +
           static_cast<std::size_t>(x);
}

bool PaintedRegions::cellOf(const double p[3], std::size_t& cell) const {
    int first[3], last[3];
    if (triangles_.empty() || !cellRange(p, p, first, last))
        return false;
    cell = cellIndex(first[0], first[1], first[2]);
    return true;
}

NearestPaint PaintedRegions::nearestIn(std::size_t cell, const double p[3], double limit_um) const {
    double best = limit_um * limit_um * (1 + 1e-12);  // a point at the limit is still reached
    std::uint32_t found = 0;
    bool any = false;
    for (std::uint32_t k = cell_start_[cell]; k < cell_start_[cell + 1]; ++k) {
        const Triangle& t = triangles_[cell_items_[k]];
        if (squaredDistanceToBox(p, t.lo, t.hi) >= best)
            continue;  // cannot be nearer
        const double d = squaredDistanceToTriangle(p, t.a, t.b, t.c);
        if (d < best) {  // the first of equally near triangles wins
            best = d;
            found = cell_items_[k];
            any = true;
        }
    }
    NearestPaint nearest;
    if (!any)
        return nearest;
    const Triangle& t = triangles_[found];
    nearest.region = region_[found];
    nearest.distance_um = std::sqrt(squaredDistanceToTriangle(p, t.a, t.b, t.c, nearest.point_um.data()));
    return nearest;
}

int PaintedRegions::regionAt(const Point3& point) const {
    const double p[3] = {static_cast<double>(point.x), static_cast<double>(point.y),
                         static_cast<double>(point.z)};
    std::size_t cell = 0;
    if (!cellOf(p, cell))
        return -1;
    return nearestIn(cell, p, depth_um_).region;
}

NearestRegions PaintedRegions::nearestRegions(const Point3& point) const {
    const double p[3] = {static_cast<double>(point.x), static_cast<double>(point.y),
                         static_cast<double>(point.z)};
    NearestRegions found;
    std::size_t cell = 0;
    if (!cellOf(p, cell))
        return found;
    found.own = nearestIn(cell, p, depth_um_);
    const int own = found.own.region;
    if (own < 0)
        return found;  // unpainted (or no paint within the depth): no other region is looked for
    double limit_sq = reach_um_ * reach_um_ * (1 + 1e-12);
    for (int r = 0; r < region_count_; ++r) {
        const NearestPaint candidate = r == own ? NearestPaint{} : nearestOf(r, p, limit_sq);
        if (candidate.region >= 0) {  // nearer than every region before it
            found.other = candidate;
            limit_sq = candidate.distance_um * candidate.distance_um;
        }
    }
    return found;
}

std::array<double, 2> PaintedRegions::distancesToRegionsUm(const std::array<double, 3>& p_um, int a, int b,
                                                           std::array<double, 2> bound_um) const {
    const double reach_sq = reach_um_ * reach_um_ * (1 + 1e-12);
    const int regions[2] = {a, b};
    std::array<double, 2> distance{};
    for (int k = 0; k < 2; ++k) {
        const double bound_sq = bound_um[static_cast<std::size_t>(k)] * bound_um[static_cast<std::size_t>(k)];
        const NearestPaint nearest =
            nearestOf(regions[k], p_um.data(), std::min(reach_sq, bound_sq * (1 + 1e-12)));
        distance[static_cast<std::size_t>(k)] =
            nearest.region >= 0 ? nearest.distance_um : std::numeric_limits<double>::infinity();
    }
    return distance;
}

}  // namespace mixengine
