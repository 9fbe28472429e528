#include "toolpaths/skin/BridgeSkin.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/PolygonOps.h"

namespace mixengine {
namespace {

/// CuraEngine's angle(): degrees of the vector measured from +y towards +x, 0 … 360, truncated.
int vectorAngle(const Point2& v) {
    double degrees = std::atan2(double(v.X), double(v.Y)) / std::numbers::pi * 180.0;
    if (degrees < 0)
        degrees += 360.0;
    return static_cast<int>(degrees);
}

double signedArea(const Path& p) {
    double a = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const Point2& u = p[i];
        const Point2& v = p[(i + 1) % p.size()];
        a += double(u.X) * double(v.Y) - double(v.X) * double(u.Y);
    }
    return a / 2;
}

Point2 centreOfMass(const Path& p) {
    double x = 0, y = 0, a = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const Point2& u = p[i];
        const Point2& v = p[(i + 1) % p.size()];
        const double cross = double(u.X) * double(v.Y) - double(v.X) * double(u.Y);
        a += cross;
        x += (double(u.X) + double(v.X)) * cross;
        y += (double(u.Y) + double(v.Y)) * cross;
    }
    if (a == 0)
        return p.empty() ? Point2{0, 0} : p.front();
    return {static_cast<coord_um>(x / (3 * a)), static_cast<coord_um>(y / (3 * a))};
}

/// The angle of the longest edge of `part` over air (−1: none over air).
int airEdgeAngle(const Paths& part, const Paths& solid_below) {
    const Box2 box = boundsOf(part);
    const coord_um grow = std::max(box.right - box.left, box.bottom - box.top);
    const Paths around{{{box.left - grow, box.top - grow},
                        {box.right + grow, box.top - grow},
                        {box.right + grow, box.bottom + grow},
                        {box.left - grow, box.bottom + grow}}};
    const Paths air = offsetMiter(differenceOf(around, solid_below), -10);
    Paths edges;
    for (const Path& loop : part) {
        for (std::size_t i = 0; i < loop.size(); ++i)
            edges.push_back({loop[i], loop[(i + 1) % loop.size()]});
    }
    double longest = 0;
    int angle = -1;
    for (const Path& piece : clipLines(edges, air)) {
        for (std::size_t i = 1; i < piece.size(); ++i) {
            const Point2 d{piece[i - 1].X - piece[i].X, piece[i - 1].Y - piece[i].Y};
            const double length2 = double(d.X) * double(d.X) + double(d.Y) * double(d.Y);
            if (length2 > longest) {
                longest = length2;
                angle = vectorAngle(d);
            }
        }
    }
    return angle;
}

/// The angle between the centres of the two largest of 1 … 5 islands (−1 otherwise).
int islandAngle(const Paths& islands) {
    if (islands.empty() || islands.size() > 5)
        return -1;
    double area1 = 0, area2 = 0;
    int first = -1, second = -1;
    for (std::size_t n = 0; n < islands.size(); ++n) {
        const double area = signedArea(islands[n]);
        if (area <= 0)
            continue;  // a hole
        if (area > area1) {
            area2 = area1, second = first;
            area1 = area, first = static_cast<int>(n);
        } else if (area > area2) {
            area2 = area, second = static_cast<int>(n);
        }
    }
    if (first < 0 || second < 0)
        return -1;
    const Point2 a = centreOfMass(islands[static_cast<std::size_t>(first)]);
    const Point2 b = centreOfMass(islands[static_cast<std::size_t>(second)]);
    return vectorAngle({b.X - a.X, b.Y - a.Y});
}

/// Whether `part` bridges over layer layer − `bridge_layer`; its line angle in `angle`.
bool bridges(const Paths& part, const BridgeSkinParams& params, const LayersBelow& below, int bridge_layer,
             int& angle) {
    const auto index = static_cast<std::size_t>(below.layer - bridge_layer);
    Paths solid = (*below.outlines)[index];
    if (bridge_layer == 1 && params.sparse_infill && below.infill)
        solid = differenceOf(solid, (*below.infill)[index]);
    const Paths islands = intersectAll(part, solid);
    if (params.support_threshold <= 0 ||
        std::abs(areaUm2(islands)) / (std::abs(areaUm2(part)) + 1) >= params.support_threshold)
        return false;
    angle = bridgeLineAngle(part, solid, islands);
    return true;
}

}  // namespace

int bridgeLineAngle(const Paths& part, const Paths& solid_below, const Paths& islands) {
    const int along_air = airEdgeAngle(part, solid_below);
    return along_air >= 0 ? along_air : islandAngle(islands);
}

BridgeSkinParams bridgeSkinParams(const Settings& s) {
    BridgeSkinParams p;
    p.enabled = s.boolean(key::bridge_settings_enabled);
    if (!p.enabled)
        return p;
    p.more_layers = s.boolean(key::bridge_enable_more_layers);
    p.support_threshold = s.ratio(key::bridge_skin_support_threshold);
    const coord_um distance = s.lengthMicrons(key::infill_line_distance);
    p.sparse_infill = distance == 0 || double(s.lengthMicrons(key::infill_line_width)) / double(distance) <=
                                           s.ratio(key::bridge_sparse_infill_max_density);
    p.bottom_layers = static_cast<int>(s.integer(key::bottom_layers));
    p.overlap_um =
        std::max(s.lengthMicrons(key::skin_overlap_mm), s.lengthMicrons(key::wall_line_width_x) / 2);
    p.layers[0] = {s.velocityMmPerS(key::bridge_skin_speed), s.ratio(key::bridge_skin_material_flow),
                   s.ratio(key::bridge_skin_density), s.ratio(key::bridge_fan_speed)};
    p.layers[1] = {s.velocityMmPerS(key::bridge_skin_speed_2), s.ratio(key::bridge_skin_material_flow_2),
                   s.ratio(key::bridge_skin_density_2), s.ratio(key::bridge_fan_speed_2)};
    p.layers[2] = {s.velocityMmPerS(key::bridge_skin_speed_3), s.ratio(key::bridge_skin_material_flow_3),
                   s.ratio(key::bridge_skin_density_3), s.ratio(key::bridge_fan_speed_3)};
    return p;
}

std::optional<SkinFillParams> bridgeSkinFill(const Paths& part, const SkinFillParams& skin,
                                             const BridgeSkinParams& params, const LayersBelow& below) {
    if (!params.enabled || below.outlines == nullptr || below.layer <= 0)
        return std::nullopt;
    int angle = -1;
    int bridge_layer = 0;
    if (bridges(part, params, below, 1, angle)) {
        bridge_layer = 1;
    } else if (params.more_layers && below.layer > 1 && params.bottom_layers > 1) {
        if (bridges(part, params, below, 2, angle))
            bridge_layer = 2;
        else if (below.layer > 2 && params.bottom_layers > 2 && bridges(part, params, below, 3, angle))
            bridge_layer = 3;
    }
    if (bridge_layer == 0)
        return std::nullopt;
    SkinFillParams fill = skin;
    if (angle >= 0) {
        const int turn[3] = {0, params.bottom_layers > 2 ? 45 : 90, 135};
        fill.angle_degrees = angle + turn[bridge_layer - 1];
    }
    const BridgeSkinLayer& style = params.layers[bridge_layer - 1];
    fill.pattern = InfillPattern::Lines;
    fill.overlap_um = params.overlap_um;
    fill.style.speed_mm_s = style.speed_mm_s;
    fill.style.flow = style.flow;
    fill.density = style.density;
    fill.bridge_fan_ratio = style.fan_ratio;
    return fill;
}

}  // namespace mixengine
