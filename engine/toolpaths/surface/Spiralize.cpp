#include "toolpaths/surface/Spiralize.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/Clip.h"
#include "geometry/PolygonOps.h"
#include "toolpaths/walls/Seam.h"

namespace mixengine {
namespace {

constexpr double kBottomStartFlow = 0.25;  ///< the bottom spiral starts at this flow
constexpr double kTopMinimumFlow = 0.25;   ///< below it the tapering round moves without extruding
constexpr double kTopCoastMm = 10.0;       ///< how far the tapering round moves without extruding

double squared(const Point2& a, const Point2& b) {
    const double dx = double(a.X - b.X), dy = double(a.Y - b.Y);
    return dx * dx + dy * dy;
}

/// The point of segment a–b nearest to p.
Point2 closestOnSegment(const Point2& p, const Point2& a, const Point2& b) {
    const double dx = double(b.X - a.X), dy = double(b.Y - a.Y);
    const double length2 = dx * dx + dy * dy;
    if (length2 <= 0)
        return a;
    const double t = std::clamp((double(p.X - a.X) * dx + double(p.Y - a.Y) * dy) / length2, 0.0, 1.0);
    return {a.X + static_cast<coord_um>(std::llround(dx * t)),
            a.Y + static_cast<coord_um>(std::llround(dy * t))};
}

/// The point of the closed loop nearest to p, and the index of the vertex its segment starts at.
std::pair<Point2, std::size_t> closestOnLoop(const Point2& p, const Path& loop) {
    double best = std::numeric_limits<double>::max();
    std::pair<Point2, std::size_t> found{loop.front(), 0};
    for (std::size_t i = 0; i < loop.size(); ++i) {
        const Point2 c = closestOnSegment(p, loop[i], loop[(i + 1) % loop.size()]);
        const double d = squared(c, p);
        if (d < best)
            best = d, found = {c, i};
    }
    return found;
}

std::size_t nearestVertex(const Point2& p, const Path& loop) {
    std::size_t best = 0;
    for (std::size_t i = 1; i < loop.size(); ++i) {
        if (squared(loop[i], p) < squared(loop[best], p))
            best = i;
    }
    return best;
}

/// The inward normal at vertex i of a counter-clockwise loop: the sum of its two edges' left
/// normals, each 10 mm long (repeated points skipped).
std::pair<double, double> inwardNormal(const Path& loop, std::size_t i) {
    const std::size_t n = loop.size();
    std::size_t before = (i + n - 1) % n, after = (i + 1) % n;
    while (before != i && loop[before] == loop[i])
        before = (before + n - 1) % n;
    while (after != i && loop[after] == loop[i])
        after = (after + 1) % n;
    auto leftNormal = [](const Point2& from, const Point2& to) {
        const double dx = double(to.X - from.X), dy = double(to.Y - from.Y);
        const double length = std::hypot(dx, dy);
        if (length <= 0)
            return std::pair<double, double>{0, 0};
        return std::pair<double, double>{-dy * 10'000 / length, dx * 10'000 / length};
    };
    const auto a = leftNormal(loop[before], loop[i]);
    const auto b = leftNormal(loop[i], loop[after]);
    return {a.first + b.first, a.second + b.second};
}

/// The seam of a layer above the one whose wall is `below` with seam `below_seam`.
std::size_t nextSeam(const Path& wall, const Path& below, std::size_t below_seam,
                     coord_um max_resolution_um) {
    const Point2& last = below[below_seam];
    std::size_t seam = nearestVertex(last, wall);
    if (std::sqrt(squared(last, wall[seam])) < double(max_resolution_um))
        return seam;
    const auto [nx, ny] = inwardNormal(below, below_seam);
    const Point2& following = wall[(seam + 1) % wall.size()];
    const double cross = nx * double(following.Y - last.Y) - ny * double(following.X - last.X);
    return cross < 0 ? seam : (seam + 1) % wall.size();  // ahead of the seam below, or one on
}

double loopLengthFrom(const Path& wall, std::size_t seam, const Point2& origin) {
    double total = 0;
    Point2 at = origin;
    for (std::size_t k = 1; k <= wall.size(); ++k) {
        const Point2& p = wall[(seam + k) % wall.size()];
        total += distanceMm(at, p);
        at = p;
    }
    return total;
}

/// The top layer's speed factor: its loop and the tapering round should take as long as the loop
/// alone would under the minimum layer time.
double topSpeedFactor(double loop_mm, const SpiralSliceParams& params) {
    if (!params.top || params.style.speed_mm_s <= 0)
        return 1.0;
    const double normal_s = loop_mm / params.style.speed_mm_s;
    if (normal_s >= params.min_layer_time_s)
        return 1.0;
    const double extended_s = loop_mm * (2 - kTopMinimumFlow) / params.style.speed_mm_s;
    return normal_s / std::min(extended_s, params.min_layer_time_s);
}

void addPoint(ExtrusionPath& path, const Point2& p, double flow) {
    path.points.push_back(p);
    path.flows.push_back(flow);
}

/// The flat tapering round of the top layer after the loop.
void appendTaper(const Path& wall, std::size_t seam, double loop_mm, double style_flow, ExtrusionPath& path) {
    double coasted = 0, printed = 0;
    Point2 at = path.points.back();
    for (std::size_t k = 1; k <= wall.size() && coasted < kTopCoastMm; ++k) {
        const Point2& p = wall[(seam + k) % wall.size()];
        const double segment = distanceMm(at, p);
        printed += segment;
        at = p;
        double flow = 1 - printed / loop_mm;
        if (flow < kTopMinimumFlow) {
            flow = 0;
            coasted += segment;
        }
        addPoint(path, p, std::floor(flow * 20) / 20.0 * style_flow);
        ++path.spiral_flat_tail;
    }
}

/// The point printed for wall point p with smoothing: moved from the nearest point of the wall below
/// towards p by the share of the loop printed, when the wall below is within two line widths.
Point2 smoothed(const Point2& p, const Path& below, double share, coord_um width_um) {
    const Point2 c = closestOnLoop(p, below).first;
    if (squared(c, p) > 4.0 * double(width_um) * double(width_um))
        return p;
    return {c.X + static_cast<coord_um>(double(p.X - c.X) * share),
            c.Y + static_cast<coord_um>(double(p.Y - c.Y) * share)};
}

}  // namespace

std::vector<std::size_t> spiralSeams(const std::vector<Path>& walls, const Point2& first_hint_um,
                                     coord_um max_resolution_um) {
    std::vector<std::size_t> seams(walls.size(), 0);
    const Path* below = nullptr;
    std::size_t below_seam = 0;
    for (std::size_t i = 0; i < walls.size(); ++i) {
        if (walls[i].size() < 3)
            continue;
        seams[i] = below ? nextSeam(walls[i], *below, below_seam, max_resolution_um)
                         : closestOnLoop(first_hint_um, walls[i]).second;
        below = &walls[i];
        below_seam = seams[i];
    }
    return seams;
}

std::vector<ExtrusionPath> spiralSlice(const Path& wall, std::size_t seam, const SpiralBelow& below,
                                       const SpiralSliceParams& params) {
    const bool continues = below.wall != nullptr && below.wall->size() >= 3;
    const Point2 origin = continues && !params.bottom ? (*below.wall)[below.seam] : wall[seam];
    ExtrusionPath path = styledPath({}, false, Feature::WallOuter, params.style);
    path.spiral = true;
    path.fixed_start = true;
    addPoint(path, origin, 0);
    const std::size_t n = wall.size();
    if (!params.smooth && continues) {  // join the wall at once, so the rest of the loop runs true
        const Point2 join = closestOnSegment(origin, wall[seam], wall[(seam + 1) % n]);
        if (squared(join, origin) > 100.0)
            addPoint(path, join, params.style.flow);
    }
    const double loop_mm = loopLengthFrom(wall, seam, origin);
    if (loop_mm <= 0)
        return {};
    double printed = 0;
    Point2 at = origin;
    for (std::size_t k = 1; k <= n; ++k) {
        const Point2& p = wall[(seam + k) % n];
        printed += distanceMm(at, p);
        at = p;
        const double share = printed / loop_mm;
        const double flow = params.bottom ? kBottomStartFlow + (1 - kBottomStartFlow) * share : 1.0;
        const bool smooth = params.smooth && continues && !params.bottom && k < n;
        addPoint(path, smooth ? smoothed(p, *below.wall, share, params.style.width_um) : p,
                 flow * params.style.flow);
    }
    if (params.top)
        appendTaper(wall, seam, loop_mm, params.style.flow, path);
    path.speed_mm_s *= topSpeedFactor(loop_mm, params);
    return {path};
}

bool spiralizeOn(const Settings& s) {
    return s.boolean(key::magic_spiralize);
}

SpiralParts splitSpiralPart(const Paths& outlines) {
    SpiralParts parts;
    std::vector<Paths> islands = splitIslands(outlines);
    for (std::size_t i = 0; i < islands.size(); ++i) {
        Paths& target = i == 0 ? parts.first : parts.others;
        target.insert(target.end(), islands[i].begin(), islands[i].end());
    }
    return parts;
}

Paths spiralWallLoops(const Paths& part, const WallParams& outer) {
    WallParams once = outer;
    once.wall_count = 1;
    once.perimeter_gaps = false;
    once.group_by_outline = false;
    Paths contours, holes;
    for (const ExtrusionPath& wall : generateWalls(part, once).walls) {
        if (wall.feature != Feature::WallOuter || wall.points.size() < 3)
            continue;
        (counterClockwise(wall.points) ? contours : holes).push_back(wall.points);
    }
    std::stable_sort(contours.begin(), contours.end(), [](const Path& a, const Path& b) {
        return std::abs(signedAreaUm2(a)) > std::abs(signedAreaUm2(b));
    });
    contours.insert(contours.end(), holes.begin(), holes.end());
    return contours;
}

namespace {

int layerCount(const Settings& s, Key<SettingUnit::Integer> key) {
    return static_cast<int>(std::clamp<long long>(s.integer(key), 0, 1'000'000));
}

/// The flat outer wall loops of initial_bottom_layers, the contour from the spiral's seam.
void appendFlatLoops(const Paths& loops, std::size_t seam, const FeatureStyle& style,
                     std::vector<ExtrusionPath>& out) {
    for (std::size_t l = 0; l < loops.size(); ++l) {
        Path points = loops[l];
        if (l == 0)
            std::rotate(points.begin(), points.begin() + static_cast<std::ptrdiff_t>(seam % points.size()),
                        points.end());
        out.push_back(styledPath(points, true, Feature::WallOuter, style));
        out.back().fixed_start = l == 0;
    }
}

}  // namespace

std::vector<std::vector<ExtrusionPath>> spiralPaths(const std::vector<Paths>& wall_loops, const Settings& s,
                                                    const Point2& mesh_centre_um, std::uint32_t sequence) {
    const std::size_t layers = wall_loops.size();
    std::vector<Path> contours(layers);
    for (std::size_t i = 0; i < layers; ++i) {
        if (!wall_loops[i].empty())
            contours[i] = wall_loops[i].front();
    }
    const SeamParams seam = seamParamsFrom(s, mesh_centre_um);
    const Point2 hint = seam.type == SeamType::Back ? seam.position_um : Point2{0, 0};
    const std::vector<std::size_t> seams =
        spiralSeams(contours, hint, s.lengthMicrons(key::meshfix_maximum_resolution));
    const int bottom = layerCount(s, key::bottom_layers);
    const int initial = layerCount(s, key::initial_bottom_layers);
    std::vector<std::vector<ExtrusionPath>> result(layers);
    for (std::size_t i = static_cast<std::size_t>(initial); i < layers; ++i) {
        if (contours[i].size() < 3)
            continue;
        SpiralSliceParams p;
        p.bottom = static_cast<int>(i) == bottom;
        p.top = i + 1 == layers || contours[i + 1].size() < 3;
        p.smooth = s.boolean(key::smooth_spiralized_contours);
        p.style = meshStyles(s, static_cast<int>(i)).wall_0;
        p.min_layer_time_s = s.durationSeconds(key::cool_min_layer_time);
        SpiralBelow below;
        if (i > 0 && contours[i - 1].size() >= 3)
            below = {&contours[i - 1], seams[i - 1]};
        if (static_cast<int>(i) == initial)
            appendFlatLoops(wall_loops[i], seams[i], p.style, result[i]);
        for (ExtrusionPath& path : spiralSlice(contours[i], seams[i], below, p))
            result[i].push_back(std::move(path));
        for (ExtrusionPath& path : result[i])
            path.sequence = sequence;
    }
    return result;
}

}  // namespace mixengine
