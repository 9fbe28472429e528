#include "mixing/PaintedRegions.h"

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

/// Squared distance from p to the point o + s·u + t·v.
double squaredToPoint(const double p[3], const double o[3], const double u[3], const double v[3], double s,
                      double t) {
    double q[3];
    for (int k = 0; k < 3; ++k)
        q[k] = o[k] + s * u[k] + t * v[k];
    return squaredTo(p, q);
}

/// Squared distance from p to the segment from o to o + u.
double squaredToSegment(const double p[3], const double o[3], const double u[3]) {
    double w[3];
    sub(p, o, w);
    const double uu = dot(u, u);
    const double s = uu > 0 ? std::clamp(dot(w, u) / uu, 0.0, 1.0) : 0.0;
    const double zero[3] = {0, 0, 0};
    return squaredToPoint(p, o, u, zero, s, 0);
}

}  // namespace

double squaredDistanceToTriangle(const double p[3], const double a[3], const double b[3], const double c[3]) {
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
            return squaredToPoint(p, a, u, v, s, t);
    }
    // Outside (or degenerate): the nearest point lies on an edge.
    double bc[3];
    sub(c, b, bc);
    return std::min({squaredToSegment(p, a, u), squaredToSegment(p, a, v), squaredToSegment(p, b, bc)});
}

PaintedRegions::PaintedRegions(const Mesh& mesh, std::vector<int> face_region, coord_um depth_um)
    : region_(std::move(face_region)), depth_um_(static_cast<double>(depth_um)) {
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

int PaintedRegions::regionAt(const Point3& point) const {
    if (triangles_.empty())
        return -1;
    const double p[3] = {static_cast<double>(point.x), static_cast<double>(point.y),
                         static_cast<double>(point.z)};
    int first[3], last[3];
    if (!cellRange(p, p, first, last))
        return -1;
    const std::size_t cell = cellIndex(first[0], first[1], first[2]);
    double best = depth_um_ * depth_um_ * (1 + 1e-12);  // a point at the depth is still painted
    int region = -1;
    for (std::uint32_t k = cell_start_[cell]; k < cell_start_[cell + 1]; ++k) {
        const Triangle& t = triangles_[cell_items_[k]];
        const double d = squaredDistanceToTriangle(p, t.a, t.b, t.c);
        if (d < best) {  // the first of equally near triangles wins
            best = d;
            region = region_[cell_items_[k]];
        }
    }
    return region;
}

}  // namespace mixengine
