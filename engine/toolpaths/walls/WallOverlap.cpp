#include "toolpaths/walls/WallOverlap.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace mixengine {
namespace {

constexpr double kMinPieceUm = 10;  // a split closer than this to another is not made
constexpr coord_um kCellUm = 2000;  // grid cell for finding the lines near a line

/// One line of a compensated loop: points[index] → points[index + 1] (cyclic) of paths[path].
struct Line {
    Point2 a, b;
    std::size_t path = 0;
    std::size_t index = 0;
    std::size_t count = 0;  // the loop's point count
};

struct Vec {
    double x = 0, y = 0;
};

Vec unitAlong(const Line& l, double length) {
    return {double(l.b.X - l.a.X) / length, double(l.b.Y - l.a.Y) / length};
}

/// Lines of one loop that share a point.
bool neighbours(const Line& s, const Line& t) {
    if (s.path != t.path)
        return false;
    return t.index == s.index || t.index == (s.index + 1) % s.count || s.index == (t.index + 1) % s.count;
}

/// How an earlier line t lies along a line s, as functions of the distance u along s: t's extent
/// projected onto s is [from, to], and the signed distance from s(u) to t's line is d0 + slope·u.
struct Beside {
    double from = 0, to = 0;
    double d0 = 0, slope = 0;
};

/// Where s(u) has a foot on t; false when nowhere along s.
bool besideOf(const Line& s, double s_length, const Line& t, Beside& out) {
    const double t_length = distanceUm(t.a, t.b);
    if (t_length <= 0)
        return false;
    const Vec ds = unitAlong(s, s_length);
    const Vec dt = unitAlong(t, t_length);
    const Vec rel{double(s.a.X - t.a.X), double(s.a.Y - t.a.Y)};
    const double c = ds.x * dt.x + ds.y * dt.y;  // cosine between the two directions
    if (c > 0)
        return false;  // running the same way: the next lines of one curve, not a pass back
    const double foot0 = rel.x * dt.x + rel.y * dt.y;  // the foot of s(0) along t
    if (std::abs(c) < 1e-9) {
        if (foot0 < 0 || foot0 > t_length)
            return false;
        out.from = 0;
        out.to = s_length;
    } else {
        const double at_start = -foot0 / c;  // u where the foot reaches t.a
        const double at_end = (t_length - foot0) / c;
        out.from = std::max(0.0, std::min(at_start, at_end));
        out.to = std::min(s_length, std::max(at_start, at_end));
    }
    out.d0 = dt.x * rel.y - dt.y * rel.x;
    out.slope = dt.x * ds.y - dt.y * ds.x;
    return out.to > out.from;
}

/// Where the overlap's width, max(0, width − |d0 + slope·u|), changes its slope, within (lo, hi).
std::vector<double> kinks(const Beside& b, double width, double lo, double hi) {
    std::vector<double> out;
    if (std::abs(b.slope) < 1e-12)
        return out;
    for (const double level : {-width, 0.0, width}) {
        const double u = (level - b.d0) / b.slope;
        if (u > lo && u < hi)
            out.push_back(u);
    }
    return out;
}

double overlapWidth(const Beside& b, double width, double u) {
    return std::max(0.0, width - std::abs(b.d0 + b.slope * u));
}

/// The overlap area over [lo, hi] of s (exact: the width is linear between its kinks).
double overlapArea(const Beside& b, double width, double lo, double hi) {
    lo = std::max(lo, b.from);
    hi = std::min(hi, b.to);
    if (hi <= lo)
        return 0;
    std::vector<double> at = kinks(b, width, lo, hi);
    at.push_back(lo);
    at.push_back(hi);
    std::sort(at.begin(), at.end());
    double area = 0;
    for (std::size_t k = 1; k < at.size(); ++k)
        area += (at[k] - at[k - 1]) * (overlapWidth(b, width, at[k - 1]) + overlapWidth(b, width, at[k])) / 2;
    return area;
}

/// The lines seen so far, by the grid cells their box grown by `reach` covers.
class LineGrid {
  public:
    explicit LineGrid(coord_um reach) : reach_(reach) {}

    void add(std::size_t id, const Line& l) {
        forCells(l, [&](std::int64_t key) { cells_[key].push_back(id); });
    }

    /// The ids of the lines added whose cells meet those of `l`, each once, ascending.
    std::vector<std::size_t> near(const Line& l) const {
        std::vector<std::size_t> out;
        forCells(l, [&](std::int64_t key) {
            const auto found = cells_.find(key);
            if (found != cells_.end())
                out.insert(out.end(), found->second.begin(), found->second.end());
        });
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end()), out.end());
        return out;
    }

  private:
    template <class F>
    void forCells(const Line& l, F&& visit) const {
        const auto cell = [](coord_um v) {
            return static_cast<std::int64_t>(std::floor(double(v) / kCellUm));
        };
        const std::int64_t x0 = cell(std::min(l.a.X, l.b.X) - reach_),
                           x1 = cell(std::max(l.a.X, l.b.X) + reach_);
        const std::int64_t y0 = cell(std::min(l.a.Y, l.b.Y) - reach_),
                           y1 = cell(std::max(l.a.Y, l.b.Y) + reach_);
        for (std::int64_t x = x0; x <= x1; ++x)
            for (std::int64_t y = y0; y <= y1; ++y)
                visit(x * 0x100000 + y);
    }

    coord_um reach_;
    std::unordered_map<std::int64_t, std::vector<std::size_t>> cells_;
};

/// One line's pieces: the points inserted inside it and the flow ratio of each piece (one more
/// ratio than points: the last piece ends at the line's end).
struct Pieces {
    std::vector<Point2> inner;
    std::vector<double> ratios;
};

Point2 pointAt(const Line& l, double length, double u) {
    const double f = u / length;
    return {l.a.X + static_cast<coord_um>(std::llround(double(l.b.X - l.a.X) * f)),
            l.a.Y + static_cast<coord_um>(std::llround(double(l.b.Y - l.a.Y) * f))};
}

/// Where the line is split: the ends of every overlap and where the distance crosses the width.
std::vector<double> splits(const std::vector<Beside>& besides, double width, double length) {
    std::vector<double> at{0.0, length};
    for (const Beside& b : besides) {
        at.push_back(b.from);
        at.push_back(b.to);
        for (const double u : kinks(b, width, b.from, b.to))
            at.push_back(u);
    }
    std::sort(at.begin(), at.end());
    std::vector<double> kept{0.0};
    for (const double u : at) {
        if (u - kept.back() >= kMinPieceUm && length - u >= kMinPieceUm)
            kept.push_back(u);
    }
    kept.push_back(length);
    return kept;
}

Pieces piecesOf(const Line& s, const std::vector<Beside>& besides, const WallOverlapParams& p) {
    const double length = distanceUm(s.a, s.b);
    const double width = double(p.width_um);
    const std::vector<double> at = splits(besides, width, length);
    Pieces out;
    for (std::size_t k = 1; k < at.size(); ++k) {
        double area = 0;
        for (const Beside& b : besides)
            area = std::max(area, overlapArea(b, width, at[k - 1], at[k]));
        const double ratio = std::clamp(1.0 - area / ((at[k] - at[k - 1]) * width), 0.0, 1.0);
        out.ratios.push_back(ratio < p.min_flow ? 0.0 : ratio);
        if (k + 1 < at.size())
            out.inner.push_back(pointAt(s, length, at[k]));
    }
    return out;
}

/// The earlier lines beside `s` closer than the width somewhere.
std::vector<Beside> earlierBeside(const Line& s, const std::vector<Line>& lines,
                                  const std::vector<std::size_t>& ids, double width) {
    std::vector<Beside> out;
    const double length = distanceUm(s.a, s.b);
    for (const std::size_t id : ids) {
        Beside b;
        if (neighbours(s, lines[id]) || !besideOf(s, length, lines[id], b))
            continue;
        if (overlapArea(b, width, b.from, b.to) > 0)
            out.push_back(b);
    }
    return out;
}

bool compensated(const ExtrusionPath& path, Feature feature) {
    return path.feature == feature && path.closed && path.points.size() >= 3 && path.flows.empty() &&
           path.air_edges.empty();
}

/// The loop rebuilt with its lines' pieces: points and per-point flows.
void rebuild(ExtrusionPath& path, const std::vector<Pieces>& pieces) {
    const std::size_t n = path.points.size();
    Path points;
    std::vector<double> flows;
    for (std::size_t k = 0; k < n; ++k) {
        points.push_back(path.points[k]);
        flows.push_back(path.flow * pieces[(k + n - 1) % n].ratios.back());
        for (std::size_t j = 0; j < pieces[k].inner.size(); ++j) {
            points.push_back(pieces[k].inner[j]);
            flows.push_back(path.flow * pieces[k].ratios[j]);
        }
    }
    path.points = std::move(points);
    path.flows = std::move(flows);
}

}  // namespace

void compensateWallOverlaps(std::vector<ExtrusionPath>& paths, Feature feature,
                            const WallOverlapParams& params) {
    std::vector<Line> lines;
    for (std::size_t i = 0; i < paths.size(); ++i) {
        if (!compensated(paths[i], feature))
            continue;
        const std::size_t n = paths[i].points.size();
        for (std::size_t k = 0; k < n; ++k)
            lines.push_back({paths[i].points[k], paths[i].points[(k + 1) % n], i, k, n});
    }
    LineGrid grid(params.width_um);
    std::unordered_map<std::size_t, std::vector<Pieces>> by_path;
    bool any = false;
    for (std::size_t id = 0; id < lines.size(); ++id) {
        const Line& s = lines[id];
        std::vector<Pieces>& pieces = by_path[s.path];
        pieces.resize(s.count);
        const std::vector<Beside> besides =
            s.a == s.b ? std::vector<Beside>{}
                       : earlierBeside(s, lines, grid.near(s), double(params.width_um));
        pieces[s.index] = besides.empty() ? Pieces{{}, {1.0}} : piecesOf(s, besides, params);
        any = any || !besides.empty();
        grid.add(id, s);
    }
    if (!any)
        return;
    for (auto& [path, pieces] : by_path)
        rebuild(paths[path], pieces);
}

}  // namespace mixengine
