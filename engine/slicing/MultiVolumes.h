#pragma once
// How the meshes of one group share space, between slicing and toolpaths, as CuraEngine 4.13 does it
// (Cura's per-model settings; the pipeline fills VolumeRole from each mesh's resolved settings):
//   - a cutting mesh (cutting_mesh) keeps only what it overlaps of the other printed meshes, and
//     those lose that part: the region prints with the cutting mesh's own settings. Support meshes,
//     support blockers and other cutting meshes are not cut;
//   - carve_multiple_volumes: where printed meshes overlap, the one later in infill_mesh_order
//     (then in the order given) loses the overlap; with alternate_carve_order and equal orders the
//     earlier mesh loses it on even layers instead. Infill meshes, support meshes, support blockers
//     and surface-mode meshes take no part;
//   - multiple_mesh_overlap: each printed mesh takes in what of the others (grown by 20 µm) lies
//     within half the overlap outside it, so touching parts bond (meshfix_union_all: non-zero fill,
//     else even-odd). Infill meshes, support meshes and support blockers take no part.
// Meshes whose bounding boxes (grown by the overlap for the last rule) do not meet are skipped.
// Every mesh has one SlicedLayer per layer of the group (the same heights); layers are processed in
// parallel (common/ParallelFor.h) and the result does not depend on `threads`.
#include <vector>

#include "mesh/Mesh.h"
#include "slicing/Slicer.h"

namespace mixengine {

struct VolumeRole {
    bool infill_mesh = false;
    bool cutting_mesh = false;
    bool support_mesh = false;
    bool anti_overhang_mesh = false;
    bool surface_only = false;  ///< magic_mesh_surface_mode "surface"
    bool union_all = true;      ///< meshfix_union_all
    int infill_mesh_order = 0;
    coord_um overlap_um = 0;  ///< multiple_mesh_overlap
    AABB3 bounds;             ///< the mesh's bounding box as placed

    /// Printed as a model of its own (walls, skin, infill) without being a modifier of others.
    bool printsAlone() const { return !infill_mesh && !support_mesh && !anti_overhang_mesh; }
    /// Puts material of its own on the plate, support meshes included (CuraEngine's Mesh::isPrinted;
    /// e.g. the slopes adaptive layers follow).
    bool printed() const { return !infill_mesh && !cutting_mesh && !anti_overhang_mesh; }
};

struct VolumeParams {
    bool carve_multiple_volumes = false;
    bool alternate_carve_order = true;
};

/// The three rules above in CuraEngine's order: cutting meshes, carving, overlap.
/// `meshes[m]` belongs to `roles[m]`.
void combineVolumes(std::vector<std::vector<SlicedLayer>>& meshes, const std::vector<VolumeRole>& roles,
                    const VolumeParams& params, int threads);

/// Whether two boxes overlap in x, y and z (touching counts), the first grown by `grow_xy_um` in x and y.
bool boxesMeet(const AABB3& a, const AABB3& b, coord_um grow_xy_um = 0);

}  // namespace mixengine
