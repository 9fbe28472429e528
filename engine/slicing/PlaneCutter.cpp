#include "slicing/PlaneCutter.h"

#include <algorithm>
#include <climits>
#include <string>

#include "common/Error.h"
#include "slicing/OutlineBuilder.h"
#include "slicing/OutlineCleanup.h"
#include "slicing/Slicer.h"

namespace mixengine {
namespace {

/// CuraEngine 4.13's last steps on a layer's loops before they are combined (SliceOptions).
void cleanLoops(std::vector<StitchedPath>& loops, const SliceOptions& options) {
    const coord_um shortest = std::max<coord_um>(options.min_circumference_um, 1);
    std::erase_if(loops, [&](const StitchedPath& loop) { return loopShorterThan(loop.points, shortest); });
    if (options.simplify_resolution_um <= 0 && options.simplify_deviation_um <= 0)
        return;
    for (StitchedPath& loop : loops)
        loop.points =
            simplifyLoop(loop.points, options.simplify_resolution_um, options.simplify_deviation_um);
    std::erase_if(loops, [](const StitchedPath& loop) { return loop.points.size() < 3; });
}

bool withinRange(const Point3& p) {
    auto ok = [](coord_um c) { return c >= -kMaxSliceCoordinateUm && c <= kMaxSliceCoordinateUm; };
    return ok(p.x) && ok(p.y) && ok(p.z);
}

}  // namespace

void validateMeshForSlicing(const Mesh& mesh) {
    if (mesh.faces.size() > static_cast<std::size_t>(INT32_MAX)) {
        throw InputError("mesh '" + mesh.name + "' has too many faces to slice (" +
                         std::to_string(mesh.faces.size()) + ")");
    }
    for (const Point3& p : mesh.vertices) {
        if (!withinRange(p)) {
            throw InputError("mesh '" + mesh.name + "' extends beyond 1 km from the origin; check its units");
        }
    }
    for (const Face& face : mesh.faces) {
        for (std::uint32_t v : face.v) {
            if (v >= mesh.vertices.size())
                throw InternalError("mesh '" + mesh.name + "': face index out of range");
        }
    }
}

Paths PlaneCutter::cut(const Mesh& mesh, std::span<const std::uint32_t> facets, coord_um plane_z,
                       OnPlaneRule rule, const SliceOptions& options, Paths& open_polylines) {
    segments_.clear();
    for (std::uint32_t f : facets) {
        const Face& face = mesh.faces[f];
        const auto segment = cutFacet(mesh.vertices[face.v[0]], mesh.vertices[face.v[1]],
                                      mesh.vertices[face.v[2]], plane_z, rule);
        if (!segment)
            continue;
        segments_.push_back(*segment);
        if (!options.curaengine_crossings) {
            segments_.back().printed_from = segment->from;
            segments_.back().printed_to = segment->to;
        }
    }
    segment_count_ += segments_.size();
    StitchResult stitched = stitcher_.stitch(segments_, options.max_gap_um);
    gap_closed_loops_ += stitched.gap_closed_loops;
    for (Path& open : stitched.open_polylines) {
        if (options.keep_open_polygons && open.size() >= 3)
            stitched.loops.push_back({open, 0.0, 0.0});  // closed by its chord, as CuraEngine 4.13
        open_polylines.push_back(std::move(open));
    }
    if (options.min_circumference_um > 0 || options.simplify_resolution_um > 0 ||
        options.simplify_deviation_um > 0)
        cleanLoops(stitched.loops, options);
    if (!options.union_all)
        return evenOddOutlines(stitched.loops, static_cast<double>(options.min_polygon_area_um2));
    return buildOutlines(stitched.loops, static_cast<double>(options.min_polygon_area_um2));
}

}  // namespace mixengine
