#include "toolpaths/walls/BridgeWalls.h"

#include <algorithm>
#include <cmath>

#include "geometry/PolygonOps.h"

namespace mixengine {
namespace {

/// The pieces of edge a → b inside `mask`, as distances along it (sorted).
std::vector<std::pair<double, double>> insidePieces(const Point2& a, const Point2& b, const Paths& mask) {
    std::vector<std::pair<double, double>> pieces;
    for (const Path& piece : clipLines({{a, b}}, mask)) {
        if (piece.size() < 2)
            continue;
        double t0 = distanceUm(a, piece.front()), t1 = distanceUm(a, piece.back());
        if (t0 > t1)
            std::swap(t0, t1);
        pieces.emplace_back(t0, t1);
    }
    std::sort(pieces.begin(), pieces.end());
    return pieces;
}

Point2 along(const Point2& a, const Point2& b, double t, double length) {
    return {a.X + static_cast<coord_um>(std::llround(double(b.X - a.X) * t / length)),
            a.Y + static_cast<coord_um>(std::llround(double(b.Y - a.Y) * t / length))};
}

}  // namespace

BridgeWallParams bridgeWallParams(const Settings& s) {
    BridgeWallParams p;
    p.enabled = s.boolean(key::bridge_settings_enabled);
    if (!p.enabled)
        return p;
    p.outer_width_um = s.lengthMicrons(key::wall_line_width_0);
    p.min_length_um = s.lengthMicrons(key::bridge_wall_min_length);
    p.style = {s.velocityMmPerS(key::bridge_wall_speed), s.ratio(key::bridge_wall_material_flow),
               s.ratio(key::bridge_fan_speed), s.ratio(key::bridge_wall_coast)};
    return p;
}

Paths bridgeWallMask(const Paths& outlines, const Paths& outlines_below, coord_um outer_width_um) {
    const coord_um half = outer_width_um / 2;
    const Paths below = offsetMiter(offsetMiter(outlines_below, -half), half);
    const Paths air = offsetMiter(differenceOf(outlines, below), -half);
    return air.empty() ? Paths{} : offsetMiter(air, 2 * half);
}

void markBridgedEdges(ExtrusionPath& wall, const Paths& mask, const BridgeWallParams& params) {
    if (mask.empty() || !wall.closed || wall.points.size() < 3)
        return;
    Path points;
    std::vector<std::uint8_t> kinds;
    bool any_air = false;
    const std::size_t n = wall.points.size();
    for (std::size_t k = 0; k < n; ++k) {
        const Point2& a = wall.points[k];
        const Point2& b = wall.points[(k + 1) % n];
        const double length = distanceUm(a, b);
        double at = 0;
        std::uint8_t continues = 0;
        points.push_back(a);
        for (const auto& [t0, t1] :
             length > 0 ? insidePieces(a, b, mask) : std::vector<std::pair<double, double>>{}) {
            if (t0 > at + 1) {  // supported up to the piece
                kinds.push_back(kSupported | continues);
                points.push_back(along(a, b, t0, length));
                continues = kContinuesEdge;
            }
            const bool end = t1 >= length - 1;
            kinds.push_back(
                std::uint8_t((t1 - t0 >= double(params.min_length_um) ? kBridged : kShortAir) | continues));
            if (!end)
                points.push_back(along(a, b, t1, length));
            continues = kContinuesEdge;
            any_air = true;
            at = t1;
        }
        if (at < length - 1 || kinds.size() < points.size())
            kinds.push_back(kSupported | continues);
    }
    if (!any_air)
        return;
    wall.points = std::move(points);
    wall.air_edges = std::move(kinds);
    wall.bridge_wall = params.style;
}

void markBridgedWalls(std::vector<ExtrusionPath>& walls, const Paths& outlines, const Paths& outlines_below,
                      const BridgeWallParams& params) {
    const Paths mask = bridgeWallMask(outlines, outlines_below, params.outer_width_um);
    if (mask.empty())
        return;
    for (ExtrusionPath& wall : walls)
        markBridgedEdges(wall, mask, params);
}

}  // namespace mixengine
