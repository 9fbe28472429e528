#include "slicing/FacetPlane.h"

#include <array>
#include <string>

#include "common/Error.h"

namespace mixengine {
namespace {

/// Index (0..2) of the only zero / only non-zero sign, given how many zeros there are.
int indexWhere(const std::array<int, 3>& signs, bool want_zero) {
    for (int i = 0; i < 3; ++i) {
        if ((signs[i] == 0) == want_zero)
            return i;
    }
    return -1;
}

FacetPlaneCase classifyTwoOnPlane(const std::array<int, 3>& signs) {
    switch (indexWhere(signs, false)) {
        case 2:
            return FacetPlaneCase::VerticesV1V2;
        case 0:
            return FacetPlaneCase::VerticesV2V3;
        default:
            return FacetPlaneCase::VerticesV3V1;
    }
}

FacetPlaneCase classifyOneOnPlane(const std::array<int, 3>& signs) {
    const int on_plane = indexWhere(signs, true);
    const int other_product = signs[(on_plane + 1) % 3] * signs[(on_plane + 2) % 3];
    const int first = other_product > 0 ? 1 : 4;  // cases 1–3 (touch) or 4–6 (vertex and opposite edge)
    return static_cast<FacetPlaneCase>(first + on_plane);
}

FacetPlaneCase classifyNoneOnPlane(const std::array<int, 3>& signs) {
    if (signs[0] == signs[1] && signs[1] == signs[2])
        return FacetPlaneCase::NoContact;
    if (signs[1] == signs[2])
        return FacetPlaneCase::EdgesL3L1;  // V1 alone
    if (signs[0] == signs[2])
        return FacetPlaneCase::EdgesL1L2;  // V2 alone
    return FacetPlaneCase::EdgesL2L3;      // V3 alone
}

coord_um roundedQuotient(coord_um numerator, coord_um positive_denominator) {
    const coord_um half = positive_denominator / 2;
    if (numerator >= 0)
        return (numerator + half) / positive_denominator;
    return -((-numerator + half) / positive_denominator);
}

bool isAbove(coord_um vertex_z, coord_um plane_z, OnPlaneRule rule) {
    return rule == OnPlaneRule::CountAsAbove ? vertex_z >= plane_z : vertex_z > plane_z;
}

/// Crossing on the edge (a, b), whose end points lie on different sides (a_above says which).
Point2 crossing(const Point3& a, const Point3& b, bool a_above, coord_um plane_z) {
    return a_above ? interpolateEdge(b, a, plane_z) : interpolateEdge(a, b, plane_z);
}

/// CuraEngine's interpolation of one coordinate at height `z` between (z0, c0) and (z1, c1).
coord_um loneInterpolate(coord_um z, coord_um z0, coord_um z1, coord_um c0, coord_um c1) {
    const coord_um dz = z1 - z0;
    coord_um numerator = (c1 - c0) * (z - z0);
    numerator += numerator > 0 ? dz / 4 : -dz / 4;
    return c0 + numerator / dz;
}

/// A vertex on the plane counts as above it (CountAsAbove); CuraEngine lifts it by 1 µm to get there.
Point3 lifted(const Point3& p, coord_um plane_z, OnPlaneRule rule) {
    if (rule == OnPlaneRule::CountAsAbove && p.z == plane_z)
        return {p.x, p.y, p.z + 1};
    return p;
}

}  // namespace

Point2 loneVertexCrossing(const Point3& lone, const Point3& other, coord_um plane_z) {
    return {loneInterpolate(plane_z, lone.z, other.z, lone.x, other.x),
            loneInterpolate(plane_z, lone.z, other.z, lone.y, other.y)};
}

FacetPlaneCase classifyFacetPlane(int sign_v1, int sign_v2, int sign_v3) {
    const std::array<int, 3> signs{sign_v1, sign_v2, sign_v3};
    int zeros = 0;
    for (int s : signs) {
        if (s < -1 || s > 1)
            throw InternalError("classifyFacetPlane: sign out of range: " + std::to_string(s));
        zeros += s == 0 ? 1 : 0;
    }
    switch (zeros) {
        case 3:
            return FacetPlaneCase::AllVertices;  // before 7–9, whose conditions it also meets
        case 2:
            return classifyTwoOnPlane(signs);
        case 1:
            return classifyOneOnPlane(signs);
        default:
            return classifyNoneOnPlane(signs);
    }
}

Point2 interpolateEdge(const Point3& lower, const Point3& upper, coord_um plane_z) {
    if (plane_z <= lower.z)
        return {lower.x, lower.y};
    if (plane_z >= upper.z)
        return {upper.x, upper.y};
    // |differences| ≤ 2·10⁹ and 0 < rise < run ≤ 2·10⁹, so the products stay below 2⁶³.
    const coord_um run = upper.z - lower.z;
    const coord_um rise = plane_z - lower.z;
    return {lower.x + roundedQuotient((upper.x - lower.x) * rise, run),
            lower.y + roundedQuotient((upper.y - lower.y) * rise, run)};
}

std::optional<FacetSegment> cutFacet(const Point3& v1, const Point3& v2, const Point3& v3, coord_um plane_z,
                                     OnPlaneRule rule) {
    const std::array<const Point3*, 3> v{&v1, &v2, &v3};
    const std::array<bool, 3> above{isAbove(v1.z, plane_z, rule), isAbove(v2.z, plane_z, rule),
                                    isAbove(v3.z, plane_z, rule)};
    const int above_count = int{above[0]} + int{above[1]} + int{above[2]};
    if (above_count == 0 || above_count == 3)
        return std::nullopt;
    // The odd vertex is alone on its side; the plane crosses the two edges meeting at it.
    const bool odd_is_above = above_count == 1;
    int odd = 0;
    while (above[odd] != odd_is_above)
        ++odd;
    const int next = (odd + 1) % 3;
    const int prev = (odd + 2) % 3;
    const Point2 on_next_edge = crossing(*v[odd], *v[next], odd_is_above, plane_z);   // edge (odd, next)
    const Point2 on_prev_edge = crossing(*v[prev], *v[odd], !odd_is_above, plane_z);  // edge (prev, odd)
    if (on_next_edge == on_prev_edge)
        return std::nullopt;  // single-vertex touch (Rule ①)
    const Point3 lone = lifted(*v[odd], plane_z, rule);
    const Point2 printed_next = loneVertexCrossing(lone, lifted(*v[next], plane_z, rule), plane_z);
    const Point2 printed_prev = loneVertexCrossing(lone, lifted(*v[prev], plane_z, rule), plane_z);
    if (odd_is_above)
        return FacetSegment{on_next_edge, on_prev_edge, printed_next, printed_prev};
    return FacetSegment{on_prev_edge, on_next_edge, printed_prev, printed_next};
}

}  // namespace mixengine
