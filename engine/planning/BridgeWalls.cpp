#include "planning/BridgeWalls.h"

#include <algorithm>
#include <cmath>

#include "planning/PathOrder.h"

namespace mixengine {
namespace {

constexpr double kFullVolume = 100'000;    // CuraEngine: MM2INT(100)
constexpr coord_um kMinLineUm = 5;         // shorter pieces are not printed
constexpr double kSpeedUpPieceUm = 1'000;  // speeding up after a bridge in 1 mm pieces
constexpr double kSpeedUpFactor = 0.75;

std::uint8_t kindOf(std::uint8_t bits) {
    return bits & 3;
}

/// The wall's state while it is printed.
struct WallRun {
    const ExtrusionPath& wall;
    const TravelParams& params;
    std::optional<Feature>& feature;
    BridgeMarks& marks;
    std::vector<PlanStep>& steps;
    Point2 head;
    double volume = kFullVolume;  ///< since the last bridge
    double speed_factor = 1;
    double to_bridge = 0;    ///< along the wall to the next bridged edge (0: none ahead)
    bool overhangs = false;  ///< the edge has an overhanging end (planning/BridgeWalls.h)

    void extrude(const Point2& to, double speed_mm_s, double flow) {
        markBridge(wall.feature, false, -1, feature, marks, steps);
        PlanStep step;
        step.kind = PlanStep::Kind::Extrude;
        step.to = to;
        step.speed_mm_s = speed_mm_s;
        step.width_um = wall.width_um;
        step.volume_mm3 = extrusionVolumeMm3(head, to, wall.width_um, params.layer_thickness_um, flow);
        steps.push_back(step);
        head = to;
    }

    void bridge(const Point2& to) {
        const BridgeWallStyle& style = *wall.bridge_wall;
        markBridge(wall.feature, true, style.fan_ratio, feature, marks, steps);
        PlanStep step;
        step.kind = PlanStep::Kind::Extrude;
        step.to = to;
        step.speed_mm_s = style.speed_mm_s;
        step.width_um = wall.width_um;
        step.volume_mm3 = extrusionVolumeMm3(head, to, wall.width_um, params.layer_thickness_um, style.flow);
        steps.push_back(step);
        head = to;
        volume = 0;
        speed_factor = std::clamp(style.speed_mm_s / wall.speed_mm_s, 0.5, 1.0);
    }

    double coastDistance() const {
        const BridgeWallStyle& style = *wall.bridge_wall;
        const double ratio = (style.speed_mm_s * style.flow) / (wall.speed_mm_s * wall.flow);
        return std::min(volume, kFullVolume) * (1 - ratio) * style.coast / 40;
    }

    /// One stretch of `length` µm towards `end`, coasting into a bridge ahead when it is near.
    void piece(const Point2& end, double flow) {
        const double length = distanceUm(head, end);
        const double coast = to_bridge > 0 ? coastDistance() : 0;
        if (to_bridge > 0 && coast > 0 && to_bridge - length <= coast) {
            const Point2 from = head;
            if (length - coast > kMinLineUm)
                extrude({end.X + static_cast<coord_um>(double(from.X - end.X) * coast / length),
                         end.Y + static_cast<coord_um>(double(from.Y - end.Y) * coast / length)},
                        wall.speed_mm_s * speed_factor, flow);
            extrude(end, wall.speed_mm_s * speed_factor, 0);
        } else {  // as CuraEngine: an overhanging edge's factor replaces the speeding up
            extrude(end, wall.speed_mm_s * (overhangs ? wall.overhang_speed_factor : speed_factor), flow);
        }
        if (to_bridge > 0)
            to_bridge -= length;
    }

    /// The supported line to `end` (speeding up after a bridge, coasting before one).
    void supported(const Point2& end) {
        double left = distanceUm(head, end);
        while (left > kMinLineUm) {
            Point2 stop = end;
            const bool coasting_near = to_bridge > 0 && to_bridge - left <= coastDistance();
            if (speed_factor < 1 && left >= kSpeedUpPieceUm && !coasting_near)
                stop = {head.X + static_cast<coord_um>(double(end.X - head.X) * kSpeedUpPieceUm / left),
                        head.Y + static_cast<coord_um>(double(end.Y - head.Y) * kSpeedUpPieceUm / left)};
            const double more = speed_factor < 1 ? 1 / speed_factor : 1;  // extrude more while slower
            const Point2 from = head;
            piece(stop, wall.flow * more);
            volume += distanceUm(from, stop) * more * speed_factor * wall.speed_mm_s;
            speed_factor = 1 - (1 - speed_factor) * kSpeedUpFactor;
            if (speed_factor >= 0.9)
                speed_factor = 1;
            left = distanceUm(head, end);
        }
    }
};

/// Whether vertex k of the wall lies over air (an edge at it crosses air).
bool overAir(const std::vector<std::uint8_t>& edges, std::size_t k) {
    const std::size_t n = edges.size();
    return kindOf(edges[k]) != kSupported || kindOf(edges[(k + n - 1) % n]) != kSupported;
}

/// The end point of the wall edge that starts at point `k` (its pieces split at air run on to it).
std::size_t edgeEnd(const ExtrusionPath& wall, std::size_t k) {
    const std::size_t n = wall.points.size();
    std::size_t end = (k + 1) % n;
    for (std::size_t t = 0; t + 1 < n && (wall.air_edges[end] & kContinuesEdge); ++t)
        end = (end + 1) % n;
    return end;
}

/// Along the wall from edge `e` (in print order from `start`) to its next bridged edge; 0 if none.
double distanceToBridge(const ExtrusionPath& wall, std::size_t start, std::size_t e) {
    const std::size_t n = wall.points.size();
    double distance = 0;
    for (std::size_t i = e; i < n; ++i) {
        const std::size_t k = (start + i) % n;
        if (kindOf(wall.air_edges[k]) == kBridged)
            return distance;
        distance += distanceUm(wall.points[k], wall.points[(k + 1) % n]);
    }
    return 0;
}

}  // namespace

void markBridge(Feature feature, bool bridge, double fan_ratio, std::optional<Feature>& current,
                BridgeMarks& marks, std::vector<PlanStep>& steps) {
    if (current != feature || marks.bridge != bridge) {
        PlanStep marker;
        marker.kind = PlanStep::Kind::SetFeature;
        marker.feature = feature;
        marker.bridge = bridge;
        steps.push_back(marker);
        current = feature;
        marks.bridge = bridge;
    }
    markFan(fan_ratio, marks, steps);
}

void markFan(double fan_ratio, BridgeMarks& marks, std::vector<PlanStep>& steps) {
    if (fan_ratio == marks.fan)
        return;
    PlanStep fan;
    fan.kind = PlanStep::Kind::SetFan;
    fan.fan_ratio = fan_ratio;
    fan.fan_fixed = fan_ratio >= 0;
    steps.push_back(fan);
    marks.fan = fan_ratio;
}

std::size_t emitBridgedWall(const ExtrusionPath& wall, std::size_t start, const TravelParams& params,
                            Point2& head, std::optional<Feature>& feature, BridgeMarks& marks,
                            std::vector<PlanStep>& steps) {
    const std::size_t n = wall.points.size();
    for (std::size_t t = 0; t < n; ++t) {
        if (!overAir(wall.air_edges, (start + t) % n) && !overhangsAt(wall, (start + t) % n)) {
            start = (start + t) % n;
            break;
        }
    }
    appendTravelTo(head, wall.points[start], params, steps);
    WallRun run{wall, params, feature, marks, steps, wall.points[start]};
    for (std::size_t e = 0; e < n; ++e) {
        const std::size_t k = (start + e) % n;
        const Point2& end = wall.points[(k + 1) % n];
        if (!(wall.air_edges[k] & kContinuesEdge)) {  // a new edge of the wall: CuraEngine's addWallLine
            run.speed_factor = 1;
            run.to_bridge = distanceToBridge(wall, start, e);
            run.overhangs = overhangsAt(wall, k) || overhangsAt(wall, edgeEnd(wall, k));
        }
        if (kindOf(wall.air_edges[k]) == kBridged && distanceUm(run.head, end) > kMinLineUm)
            run.bridge(end);
        else
            run.supported(end);
    }
    head = run.head;
    return start;
}

bool overhangsAt(const ExtrusionPath& path, std::size_t k) {
    return path.overhanging.size() == path.points.size() && k < path.overhanging.size() &&
           path.overhanging[k] != 0;
}

std::size_t firstNonOverhanging(const ExtrusionPath& path, std::size_t start) {
    const std::size_t n = path.points.size();
    if (path.overhanging.size() != n)
        return start;
    for (std::size_t t = 0; t < n; ++t) {
        if (!overhangsAt(path, (start + t) % n))
            return (start + t) % n;
    }
    return start;
}

double overhangSpeedFactor(const ExtrusionPath& path, std::size_t from, std::size_t to) {
    return overhangsAt(path, from) || overhangsAt(path, to) ? path.overhang_speed_factor : 1.0;
}

}  // namespace mixengine
