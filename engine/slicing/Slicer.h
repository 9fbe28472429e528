#pragma once
// The slicer: cuts a Mesh with horizontal planes into closed outlines (seed 003, done better).
//
// Contract:
//   - every facet is classified against the plane into the 14 cases of seed 003 (slicing/FacetPlane.h);
//     a vertex exactly on the plane never yields duplicate or dangling segments; horizontal facets
//     in the plane count when facing up and not when facing down;
//   - intersection points are computed exactly by interpolation along the edge (no bisection);
//   - segments are stitched into polygons in linear time through a hash of their end points; small
//     gaps (≤ max_gap_um, nearest ends first) are closed; polylines that cannot be closed are reported in
//     `open_polylines` and are not part of `outlines`;
//   - outlines are the union of all closed loops (overlapping shells merged, holes by nesting,
//     independent of facet winding): outer contours counter-clockwise, holes clockwise
//     (slicing/OutlineBuilder.h has the exact rules);
//   - a cut at height z is taken just below z (vertices on the plane count as above it,
//     slicing/FacetPlane.h): a plane through the top face of a body still cuts the body, a plane
//     through its bottom face does not;
//   - slicing_tolerance: middle cuts at LayerZ::slice_z; inclusive / exclusive cut (just below, as
//     every cut) at the slab's top (print_z) and its bottom (bottom_z; under layer 0 at z = 0 for
//     inclusive, at max(0, layer_height_0 − layer_height) for exclusive) and take the union /
//     intersection; the last layer is its bottom cut alone (inclusive) or empty (exclusive). As in
//     CuraEngine 4.13, a body standing on z = 0 is then missing from layer 0 with exclusive (the
//     empty bottom layer is dropped later, toolpaths/EmptyLayers.h; the empty last layer is written,
//     where CuraEngine counts it in ;LAYER_COUNT: but writes no ;LAYER: for it);
//   - only facets whose z-range contains a plane are cut there (slicing/FacetBuckets.h); layers are
//     sliced in parallel (common/ParallelFor.h); the result does not depend on the thread count.
// Errors: InputError for a mesh beyond ±1 km (the exact 64-bit interpolation's range), InternalError
// for a face index out of range. A warning names the mesh when open polylines were left out.
#include <vector>

#include "common/Log.h"
#include "geometry/Point.h"
#include "mesh/Mesh.h"
#include "slicing/LayerHeights.h"

namespace mixengine {

struct SliceOptions {
    SlicingTolerance tolerance = SlicingTolerance::Middle;
    coord_um max_gap_um = 100;          ///< gaps up to this size are closed while stitching
    coord_um min_polygon_area_um2 = 0;  ///< loops with |area| below this are dropped (noise)
    int threads = 2;                    ///< layers are sliced in parallel (values < 1 mean 1)
    /// meshfix_union_all: overlapping shells united (slicing/OutlineBuilder.h); off: even-odd.
    bool union_all = true;
    /// meshfix_keep_open_polygons: open pieces closed by their chord and kept in the outlines too.
    bool keep_open_polygons = false;
    /// What CuraEngine 4.13's slicer does to each loop before the loops are combined: loops shorter
    /// than this go (lengths summed in whole microns, as CuraEngine), then every loop is simplified
    /// (slicing/OutlineCleanup.h simplifyLoop) with this resolution and deviation. All 0: raw cuts.
    coord_um min_circumference_um = 0;
    /// Outline vertices where CuraEngine 4.13's slicer puts them (FacetSegment's printed points:
    /// its rounding, a vertex on the plane lifted by 1 µm); off: the exact crossings.
    bool curaengine_crossings = false;
    coord_um simplify_resolution_um = 0;
    coord_um simplify_deviation_um = 0;
};

struct SlicedLayer {
    coord_um print_z = 0;
    coord_um slice_z = 0;
    Paths outlines;        ///< closed, unioned; outer CCW, holes CW
    Paths open_polylines;  ///< pieces that could not be closed (kept out of outlines)
};

/// Cuts the mesh at every layer of `layers`; result[i] belongs to layers[i].
std::vector<SlicedLayer> sliceMesh(const Mesh& mesh, const std::vector<LayerZ>& layers,
                                   const SliceOptions& options, Log& log);

/// One plane only, cut just below z (used by tests and by the cut at exact heights);
/// options.tolerance and options.threads are not used; open pieces are not logged.
SlicedLayer slicePlane(const Mesh& mesh, coord_um z, const SliceOptions& options);

}  // namespace mixengine
