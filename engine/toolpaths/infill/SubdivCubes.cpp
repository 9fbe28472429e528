#include "toolpaths/infill/SubdivCubes.h"

#include <cmath>
#include <cstdlib>
#include <limits>

#include "geometry/Angles.h"
#include "geometry/Clip.h"

namespace mixengine {
namespace {

constexpr double kOneOverSqrt2 = 0.70710678118654752440;
constexpr double kOneOverSqrt3 = 0.57735026918962576451;
constexpr double kOneOverSqrt6 = 0.40824829046386301637;
constexpr double kSqrtTwoThirds = 0.81649658092772603273;
constexpr double kSqrtThreeFourths = 0.86602540378443864676;

/// 0 outside, 1 inside (even-odd over all loops); `distance2` the squared distance to the boundary.
bool insideWithDistance(const Paths& loops, const Point2& p, double& distance2) {
    bool inside = false;
    distance2 = std::numeric_limits<double>::max();
    for (const Path& loop : loops) {
        if (pointInLoop(p, loop) != 0)
            inside = !inside;
        for (std::size_t i = 0; i < loop.size(); ++i) {
            const Point2& a = loop[i];
            const Point2& b = loop[(i + 1) % loop.size()];
            const double dx = double(b.X - a.X), dy = double(b.Y - a.Y);
            const double length2 = dx * dx + dy * dy;
            double t = length2 > 0 ? (double(p.X - a.X) * dx + double(p.Y - a.Y) * dy) / length2 : 0.0;
            t = std::clamp(t, 0.0, 1.0);
            const double ex = double(a.X) + t * dx - double(p.X), ey = double(a.Y) + t * dy - double(p.Y);
            distance2 = std::min(distance2, ex * ex + ey * ey);
        }
    }
    return inside;
}

bool near(const Point2& a, const Point2& b) {
    return std::llabs(a.X - b.X) < 10 && std::llabs(a.Y - b.Y) < 10;
}

/// Adds the line from → to to `group`, joined with lines ending at `from` or starting at `to`.
void addJoined(Path from_to, Paths& group) {
    bool joined = true;
    while (joined) {
        joined = false;
        for (std::size_t i = 0; i < group.size(); ++i) {
            if (near(from_to[0], group[i][1]))
                from_to[0] = group[i][0];
            else if (near(from_to[1], group[i][0]))
                from_to[1] = group[i][1];
            else
                continue;
            group[i] = group.back();
            group.pop_back();
            joined = true;
            break;
        }
    }
    group.push_back(std::move(from_to));
}

Point2 rotate120(const Point2& p) {
    return {static_cast<coord_um>(-0.5 * double(p.X) - kSqrtThreeFourths * double(p.Y)),
            static_cast<coord_um>(-0.5 * double(p.Y) + kSqrtThreeFourths * double(p.X))};
}

}  // namespace

SubdivCubes::SubdivCubes(const SubdivCubeParams& params, const std::vector<Paths>& boundaries)
    : params_(params) {
    if (params.line_distance_um <= 0)
        return;
    const Point3& m = params.machine_size_um;
    const double furthest = std::sqrt(double(m.z) * double(m.z) + double(m.y / 2) * double(m.y / 2) +
                                      double(m.x / 2) * double(m.x / 2));
    const coord_um max_side = 2 * static_cast<coord_um>(furthest);
    for (coord_um side = 2 * params.line_distance_um; side < max_side * 2; side *= 2) {
        levels_.push_back({side, static_cast<coord_um>(std::sqrt(3.0) * double(side)),
                           static_cast<coord_um>(std::sqrt(2.0) * double(side)),
                           static_cast<coord_um>(kOneOverSqrt3 * double(side)),
                           static_cast<coord_um>(kOneOverSqrt6 * double(side))});
    }
    const double a = radiansFromDegrees(params.angle_degrees);
    cos_a_ = std::cos(a);
    sin_a_ = std::sin(a);
    const double turn[9] = {cos_a_, -sin_a_, 0, sin_a_, cos_a_, 0, 0, 0, 1};
    const double tilt[9] = {-kOneOverSqrt2, kOneOverSqrt2,  0,
                            -kOneOverSqrt6, -kOneOverSqrt6, kSqrtTwoThirds,
                            kOneOverSqrt3,  kOneOverSqrt3,  kOneOverSqrt3};
    for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 3; ++col)
            for (int k = 0; k < 3; ++k)
                rotation_[row * 3 + col] += turn[row * 3 + k] * tilt[k * 3 + col];
    cubes_.push_back({{params.origin_um.X, params.origin_um.Y, 0}, levels_.size() - 1, {}});
    subdivide(0, boundaries);
}

void SubdivCubes::subdivide(std::size_t cube, const std::vector<Paths>& boundaries) {
    const std::size_t depth = cubes_[cube].depth;
    if (depth == 0)
        return;
    const Level& level = levels_[depth];
    const coord_um radius = static_cast<coord_um>(double(level.height) / 4.0) + params_.radius_addition_um;
    const coord_um quarter = level.side / 4;
    static constexpr int kCorners[8][3] = {{1, 1, 1},    {-1, 1, 1},  {1, -1, 1},  {1, 1, -1},
                                           {-1, -1, -1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
    for (const auto& corner : kCorners) {
        const double v[3] = {double(corner[0] * quarter), double(corner[1] * quarter),
                             double(corner[2] * quarter)};
        const Point3& c = cubes_[cube].centre;
        const Point3 child{
            c.x + static_cast<coord_um>(rotation_[0] * v[0] + rotation_[1] * v[1] + rotation_[2] * v[2]),
            c.y + static_cast<coord_um>(rotation_[3] * v[0] + rotation_[4] * v[1] + rotation_[5] * v[2]),
            c.z + static_cast<coord_um>(rotation_[6] * v[0] + rotation_[7] * v[1] + rotation_[8] * v[2])};
        if (!reachesBoundary(child, radius, boundaries))
            continue;
        cubes_.push_back({child, depth - 1, {}});
        const std::size_t index = cubes_.size() - 1;
        cubes_[cube].children.push_back(index);
        subdivide(index, boundaries);
    }
}

bool SubdivCubes::reachesBoundary(const Point3& centre, coord_um radius,
                                  const std::vector<Paths>& boundaries) const {
    const coord_um h = std::max<coord_um>(params_.layer_height_um, 1);
    bool inside_somewhere = false, outside_somewhere = false;
    for (coord_um layer = (centre.z - radius) / h; layer <= (centre.z + radius) / h; layer += 3) {
        const double part = double(layer * h - centre.z) / double(radius);
        const double slice_radius2 = double(radius) * double(radius) * (1.0 - part * part);
        const bool known = layer >= 0 && layer < static_cast<coord_um>(boundaries.size());
        double distance2 = std::numeric_limits<double>::max();
        const bool inside = known && insideWithDistance(boundaries[static_cast<std::size_t>(layer)],
                                                        {centre.x, centre.y}, distance2);
        (inside ? inside_somewhere : outside_somewhere) = true;
        if ((inside_somewhere && outside_somewhere) || (known && distance2 < slice_radius2))
            return true;
    }
    return false;
}

void SubdivCubes::addLines(const Cube& cube, coord_um z, Paths (&by_direction)[3]) const {
    const Level& level = levels_[cube.depth];
    const coord_um z_diff = std::llabs(z - cube.centre.z);
    if (z_diff > level.height / 2)
        return;
    if (z_diff < level.max_draw_z_diff) {
        const coord_um half_x =
            (level.square_height / 2) * (level.max_draw_z_diff - z_diff) / level.max_draw_z_diff;
        const coord_um y =
            static_cast<coord_um>(double(level.max_line_offset) -
                                  double(z - (cube.centre.z - level.max_draw_z_diff)) * kOneOverSqrt2);
        auto turn = [&](coord_um x) {
            return Point2{static_cast<coord_um>(double(x) * cos_a_ - double(y) * sin_a_),
                          static_cast<coord_um>(double(x) * sin_a_ + double(y) * cos_a_)};
        };
        Point2 a = turn(half_x), b = turn(-half_x);
        for (Paths& group : by_direction) {
            addJoined(
                {{cube.centre.x + a.X, cube.centre.y + a.Y}, {cube.centre.x + b.X, cube.centre.y + b.Y}},
                group);
            a = rotate120(a);
            b = rotate120(b);
        }
    }
    for (std::size_t child : cube.children)
        addLines(cubes_[child], z, by_direction);
}

Paths SubdivCubes::linesAt(coord_um z_um) const {
    if (cubes_.empty())
        return {};
    Paths by_direction[3];
    addLines(cubes_[0], z_um, by_direction);
    Paths lines;
    for (Paths& group : by_direction)
        lines.insert(lines.end(), group.begin(), group.end());
    return lines;
}

}  // namespace mixengine
