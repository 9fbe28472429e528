#include "slicing/MultiVolumes.h"

#include <algorithm>
#include <numeric>

#include "common/ParallelFor.h"
#include "geometry/Clip.h"

namespace mixengine {
namespace {

Paths clip(const Paths& a, const Paths& b, ClipOp type, FillRule fill = FillRule::NonZero) {
    return clipAreas(a, b, type, fill);
}

Paths grown(const Paths& area, coord_um delta_um) {
    // CuraEngine's mitred offset (miter limit 1.2), Clipper's default arc tolerance (0.25 µm)
    return offsetMitred(area, static_cast<double>(delta_um), OffsetEnds::ClosedPolygon, 1.2, 0.25);
}

bool cuttable(const VolumeRole& role) {
    return !role.cutting_mesh && !role.support_mesh && !role.anti_overhang_mesh;
}

bool carves(const VolumeRole& role) {
    return role.printsAlone() && !role.surface_only;
}

/// Every cutting mesh, in the order given, takes its overlap with the cuttable meshes from them.
void cutWithCuttingMeshes(std::vector<std::vector<SlicedLayer>>& meshes, const std::vector<VolumeRole>& roles,
                          int threads) {
    for (std::size_t c = 0; c < meshes.size(); ++c) {
        if (!roles[c].cutting_mesh)
            continue;
        parallelFor(meshes[c].size(), threads, [&](std::size_t layer) {
            Paths& cutter = meshes[c][layer].outlines;
            Paths region;
            for (std::size_t m = 0; m < meshes.size(); ++m) {
                if (!cuttable(roles[m]) || layer >= meshes[m].size())
                    continue;
                Paths& carved = meshes[m][layer].outlines;
                const Paths part = clip(cutter, carved, ClipOp::Intersection);
                region.insert(region.end(), part.begin(), part.end());
                carved = clip(carved, cutter, ClipOp::Difference);
            }
            cutter = clip(region, {}, ClipOp::Union);
        });
    }
}

/// carve_multiple_volumes (see the header).
void carveOverlaps(std::vector<std::vector<SlicedLayer>>& meshes, const std::vector<VolumeRole>& roles,
                   bool alternate, int threads) {
    std::vector<std::size_t> ranked(meshes.size());
    std::iota(ranked.begin(), ranked.end(), std::size_t{0});
    std::stable_sort(ranked.begin(), ranked.end(), [&](std::size_t a, std::size_t b) {
        return roles[a].infill_mesh_order < roles[b].infill_mesh_order;
    });
    for (std::size_t i = 1; i < ranked.size(); ++i) {
        const std::size_t later = ranked[i];
        if (!carves(roles[later]))
            continue;
        for (std::size_t j = 0; j < i; ++j) {
            const std::size_t earlier = ranked[j];
            if (!carves(roles[earlier]) || !boxesMeet(roles[later].bounds, roles[earlier].bounds))
                continue;
            const bool same_order = roles[later].infill_mesh_order == roles[earlier].infill_mesh_order;
            const std::size_t layers = std::min(meshes[later].size(), meshes[earlier].size());
            parallelFor(layers, threads, [&](std::size_t layer) {
                Paths& a = meshes[later][layer].outlines;
                Paths& b = meshes[earlier][layer].outlines;
                if (alternate && same_order && layer % 2 == 0)
                    b = clip(b, a, ClipOp::Difference);
                else
                    a = clip(a, b, ClipOp::Difference);
            });
        }
    }
}

/// multiple_mesh_overlap (see the header), mesh after mesh: a mesh sees the others as grown so far.
void overlapVolumes(std::vector<std::vector<SlicedLayer>>& meshes, const std::vector<VolumeRole>& roles,
                    int threads) {
    constexpr coord_um kMergeUm = 20;
    if (meshes.size() < 2)
        return;
    for (std::size_t v = 0; v < meshes.size(); ++v) {
        const VolumeRole& role = roles[v];
        if (!role.printsAlone() || role.overlap_um == 0)
            continue;
        const FillRule fill = role.union_all ? FillRule::NonZero : FillRule::EvenOdd;
        parallelFor(meshes[v].size(), threads, [&](std::size_t layer) {
            Paths others;
            for (std::size_t o = 0; o < meshes.size(); ++o) {
                if (o == v || !roles[o].printsAlone() || layer >= meshes[o].size() ||
                    !boxesMeet(role.bounds, roles[o].bounds, role.overlap_um))
                    continue;
                others = clip(others, grown(meshes[o][layer].outlines, kMergeUm), ClipOp::Union, fill);
            }
            Paths& own = meshes[v][layer].outlines;
            const Paths reach = clip(others, grown(own, role.overlap_um / 2), ClipOp::Intersection);
            own = clip(own, reach, ClipOp::Union, fill);
        });
    }
}

}  // namespace

bool boxesMeet(const AABB3& a, const AABB3& b, coord_um grow_xy_um) {
    if (a.empty() || b.empty())
        return false;
    return a.min.x - grow_xy_um <= b.max.x && b.min.x <= a.max.x + grow_xy_um &&
           a.min.y - grow_xy_um <= b.max.y && b.min.y <= a.max.y + grow_xy_um && a.min.z <= b.max.z &&
           b.min.z <= a.max.z;
}

void combineVolumes(std::vector<std::vector<SlicedLayer>>& meshes, const std::vector<VolumeRole>& roles,
                    const VolumeParams& params, int threads) {
    cutWithCuttingMeshes(meshes, roles, threads);
    if (params.carve_multiple_volumes)
        carveOverlaps(meshes, roles, params.alternate_carve_order, threads);
    overlapVolumes(meshes, roles, threads);
}

}  // namespace mixengine
