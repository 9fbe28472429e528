#pragma once
// One facet against one horizontal plane z = z0 (seed 003, step 3, done exactly in integer microns).
//
// Classification (`classifyFacetPlane`): the signs s_i = sign(V_i.z − z0) select one of the 14
// cases of seed 003. The 27 sign patterns map onto the 14 cases without gaps; case 13 (all three
// vertices on the plane) is tested before cases 7–9 because it also satisfies their conditions.
// Edges: L1 = V1V2, L2 = V2V3, L3 = V3V1.
//
// Segment (`cutFacet`): the classification describes where the plane touches the facet; which
// facets produce a segment is decided by symbolic perturbation instead. A vertex exactly on the
// plane is treated as lying infinitesimally above it (OnPlaneRule::CountAsAbove, i.e. the cut is
// taken at z0 − ε) or below it (CountAsBelow, z0 + ε). With every vertex strictly on one side,
// a facet is either not crossed or crossed on exactly the two edges at its "odd" vertex, so
//   - each facet yields at most one segment;
//   - the two facets sharing a crossed edge compute the same end point (the edge is interpolated
//     from its lower to its upper vertex, an order both facets agree on), so every closed surface
//     gives closed loops, without duplicate or dangling segments at vertices on the plane.
// How this relates to seed 003's acceptance rules (with CountAsAbove):
//   - Rule ① (single-vertex touch, cases 1–3, is rejected): the perturbed facet is either not
//     crossed or both crossings collapse onto the touching vertex; a zero-length segment is
//     dropped. Cases 4–6 give the segment from the vertex to the opposite edge, as Rule ① keeps.
//   - Rule ② (edge in the plane, cases 7–9: keep the facet on one side only): the facet whose
//     third vertex lies below the plane yields the edge, the one whose third vertex lies above
//     yields nothing. The seed's prose picks "above"; either side closes the loops, and "below"
//     makes a plane through the top of a body still cut it.
//   - Case 13 (facet in the plane) never yields a segment itself. Its neighbours decide: at a
//     top face (upward-facing) the side facets reach up to the plane from below, so the cut is the
//     face's full outline — an upward-facing facet in the plane counts; at a bottom face
//     (downward-facing) the side facets lie above, so it does not count (PrusaSlicer's
//     convention). CountAsBelow mirrors all of this (a bottom face counts, a top face does not).
// Direction: for a facet wound counter-clockwise seen from outside, the segment runs so that the
// solid is on its left seen from above (outer contours come out counter-clockwise).
#include <cstdint>
#include <optional>

#include "geometry/Point.h"

namespace mixengine {

/// Seed 003's 14 cases, numbered as in the paper (static_cast<int> gives the number).
enum class FacetPlaneCase : std::uint8_t {
    VertexV1 = 1,        ///< P(V1) = 0, P(V2)·P(V3) > 0
    VertexV2 = 2,        ///< P(V2) = 0, P(V3)·P(V1) > 0
    VertexV3 = 3,        ///< P(V3) = 0, P(V1)·P(V2) > 0
    VertexV1EdgeL2 = 4,  ///< P(V1) = 0, P(V2)·P(V3) < 0
    VertexV2EdgeL3 = 5,  ///< P(V2) = 0, P(V3)·P(V1) < 0
    VertexV3EdgeL1 = 6,  ///< P(V3) = 0, P(V1)·P(V2) < 0
    VerticesV1V2 = 7,    ///< P(V1) = P(V2) = 0 (edge L1 in the plane)
    VerticesV2V3 = 8,    ///< P(V2) = P(V3) = 0 (edge L2 in the plane)
    VerticesV3V1 = 9,    ///< P(V3) = P(V1) = 0 (edge L3 in the plane)
    EdgesL1L2 = 10,      ///< V2 alone on its side
    EdgesL2L3 = 11,      ///< V3 alone on its side
    EdgesL3L1 = 12,      ///< V1 alone on its side
    AllVertices = 13,    ///< the facet lies in the plane
    NoContact = 14,      ///< all three strictly on one side
};

/// −1, 0 or +1: the side of the plane z = plane_z the height vertex_z is on.
inline int planeSign(coord_um vertex_z, coord_um plane_z) {
    return (vertex_z > plane_z) - (vertex_z < plane_z);
}

/// The case of seed 003 for the signs of V1, V2, V3 (each −1, 0 or +1). Throws InternalError for
/// other values.
FacetPlaneCase classifyFacetPlane(int sign_v1, int sign_v2, int sign_v3);

/// Where a vertex exactly on the plane is taken to be (the symbolic perturbation).
enum class OnPlaneRule : std::uint8_t {
    CountAsAbove,  ///< cut at z0 − ε: a top face in the plane counts, a bottom face does not
    CountAsBelow,  ///< cut at z0 + ε: a bottom face in the plane counts, a top face does not
};

/// A directed cut segment in microns (solid on the left for outward-facing facets). `from` / `to`
/// are the exact crossings both facets at an edge agree on (for chaining); `printed_from` /
/// `printed_to` are the same crossings as CuraEngine 4.13's slicer computes them (interpolated from
/// the facet's lone vertex with its rounding, a vertex on the plane lifted by 1 µm), which become
/// the outline's vertices. They differ by at most a few microns.
struct FacetSegment {
    Point2 from;
    Point2 to;
    Point2 printed_from = from;
    Point2 printed_to = to;
};

/// The crossing of the edge (a, b) with the plane, where `lower` is strictly below and `upper` on
/// or above it in the perturbed sense (lower.z < upper.z, lower.z ≤ plane_z ≤ upper.z). Exact
/// interpolation with rounding to the nearest micron (halves away from zero); an end point on the
/// plane is returned as is. Coordinates must lie within ±kMaxSliceCoordinateUm.
Point2 interpolateEdge(const Point3& lower, const Point3& upper, coord_um plane_z);

/// CuraEngine 4.13's crossing of the edge from `lone` (the vertex alone on its side) to `other`:
/// interpolated from `lone`, with the quotient rounded by adding a quarter of the height
/// difference and truncating, as its slicer does. The heights must differ.
Point2 loneVertexCrossing(const Point3& lone, const Point3& other, coord_um plane_z);

/// The segment the facet (v1, v2, v3) contributes to the cut at plane_z, if any (see above).
std::optional<FacetSegment> cutFacet(const Point3& v1, const Point3& v2, const Point3& v3, coord_um plane_z,
                                     OnPlaneRule rule);

/// Largest |coordinate| the exact 64-bit interpolation supports (1 km in microns).
constexpr coord_um kMaxSliceCoordinateUm = 1'000'000'000;

}  // namespace mixengine
