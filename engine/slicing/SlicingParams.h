#pragma once
// The slicing stage's parameters, built here from the resolved settings (settings/SettingKeys.h): how
// layers are placed and cut, how a mesh's cut pieces are joined and cleaned, and what part each mesh
// plays in its group.
#include "geometry/Point.h"
#include "mesh/Mesh.h"
#include "settings/Settings.h"
#include "slicing/AdaptiveLayers.h"
#include "slicing/LayerHeights.h"
#include "slicing/MultiVolumes.h"
#include "slicing/Slicer.h"

namespace mixengine {

/// slicing_tolerance: where in a layer its cut is taken.
SlicingTolerance slicingToleranceOf(const Settings& group);

/// adaptive_layer_height_* (slicing/AdaptiveLayers.h).
AdaptiveLayerParams adaptiveLayerParams(const Settings& group, SlicingTolerance tolerance);

/// How far apart the ends of open cut pieces may be and still be joined: as CuraEngine 4.13, up to
/// 10 mm (nearest ends first, pieces reversed where needed), so an open scan still slices into
/// closed outlines; in a mesh surface mode only the slicer's own 0.1 mm (open pieces stay open).
coord_um stitchDistanceUm(const Settings& mesh);

/// What the slicer does to each stitched loop (SliceOptions): minimum_polygon_circumference, and for a
/// print (`simplify`) CuraEngine 4.13's crossings and its slicer simplification (10 µm / 5 µm;
/// meshfix_maximum_resolution / _deviation act on the walls, not here); `mixengine layers` shows the
/// exact cuts unsimplified.
void setOutlineCleanup(SliceOptions& options, const Settings& group, bool simplify);

/// The mesh's part in its group from its resolved settings (infill_mesh, cutting_mesh, support_mesh,
/// anti_overhang_mesh, infill_mesh_order, multiple_mesh_overlap, meshfix_union_all, …).
VolumeRole volumeRoleOf(const Settings& mesh_settings, const Mesh& mesh);

/// carve_multiple_volumes, alternate_carve_order.
VolumeParams volumeParams(const Settings& group);

}  // namespace mixengine
