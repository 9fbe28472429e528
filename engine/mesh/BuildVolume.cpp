#include "mesh/BuildVolume.h"

#include <algorithm>
#include <cstdio>

#include "common/Error.h"

namespace mixengine {
namespace {

/// "12.5" for 12500 microns: millimetres with up to 3 decimals, no trailing zeros.
std::string mm(coord_um um) {
    char text[48];
    std::snprintf(text, sizeof text, "%.3f", micronsToMm(um));
    std::string s = text;
    while (s.back() == '0')
        s.pop_back();
    if (s.back() == '.')
        s.pop_back();
    return s;
}

std::string size(const Point3& lo, const Point3& hi) {
    return mm(hi.x - lo.x) + " x " + mm(hi.y - lo.y) + " x " + mm(hi.z - lo.z) + " mm";
}

std::string span(const Point3& lo, const Point3& hi) {
    return "x " + mm(lo.x) + ".." + mm(hi.x) + ", y " + mm(lo.y) + ".." + mm(hi.y) + ", z " + mm(lo.z) +
           ".." + mm(hi.z) + " mm";
}

/// True when `extent` exceeds kMaxOversize times `room` (a room of 0 or less is not checked).
bool farLarger(coord_um extent, coord_um room) {
    return room > 0 && static_cast<double>(extent) > kMaxOversize * static_cast<double>(room);
}

}  // namespace

BuildVolume machineVolume(coord_um width, coord_um depth, coord_um height, bool center_is_zero) {
    if (center_is_zero)
        return {{-width / 2, -depth / 2, 0}, {width - width / 2, depth - depth / 2, height}};
    return {{0, 0, 0}, {width, depth, height}};
}

std::string checkBuildVolume(const std::string& name, const AABB3& mesh_box, const BuildVolume& volume) {
    if (mesh_box.empty())
        return {};
    const Point3& lo = mesh_box.min;
    const Point3& hi = mesh_box.max;
    const Point3& vlo = volume.min;
    const Point3& vhi = volume.max;
    constexpr coord_um kOneKm = 1'000'000'000;
    if (std::max({-lo.x, -lo.y, -lo.z, hi.x, hi.y, hi.z}) > kOneKm) {
        throw InputError(name + ": placed at " + span(lo, hi) +
                         ", beyond 1 km from the origin (placement by machine_width, machine_depth, "
                         "machine_center_is_zero, mesh_position_x/y/z); check the units");
    }
    if (farLarger(hi.x - lo.x, vhi.x - vlo.x) || farLarger(hi.y - lo.y, vhi.y - vlo.y) ||
        farLarger(hi.z - lo.z, vhi.z - vlo.z)) {
        char factor[16];
        std::snprintf(factor, sizeof factor, "%g", kMaxOversize);
        throw InputError(name + ": the model is " + size(lo, hi) + ", more than " + factor +
                         " times the build volume (" + size(vlo, vhi) +
                         ": machine_width, machine_depth, machine_height); wrong units?");
    }
    if (lo.x >= vlo.x && lo.y >= vlo.y && lo.z >= vlo.z && hi.x <= vhi.x && hi.y <= vhi.y && hi.z <= vhi.z)
        return {};
    return name + ": the model (" + span(lo, hi) + ") reaches outside the build volume (" + span(vlo, vhi) +
           "); it is sliced as placed";
}

}  // namespace mixengine
