#include "slicing/Slicer.h"

#include <algorithm>
#include <atomic>
#include <mutex>
#include <string>

#include "common/ParallelFor.h"
#include "geometry/Clip.h"
#include "slicing/FacetBuckets.h"
#include "slicing/PlaneCutter.h"

namespace mixengine {
namespace {

/// One cut of a layer: a plane (index into the sorted heights) and the side it is taken on.
struct Cut {
    std::size_t plane = 0;
    OnPlaneRule rule = OnPlaneRule::CountAsAbove;
};

/// The heights to cut at (ascending, unique) and, per layer, its one or two cuts.
struct CutPlan {
    std::vector<coord_um> plane_z;
    std::vector<std::vector<Cut>> layer_cuts;
};

std::size_t planeIndex(const std::vector<coord_um>& plane_z, coord_um z) {
    return static_cast<std::size_t>(std::lower_bound(plane_z.begin(), plane_z.end(), z) - plane_z.begin());
}

/// The plane under layer i for inclusive / exclusive, as CuraEngine 4.13 places it: the bottom of
/// the slab, except under layer 0: z = 0 (inclusive) or layer_height_0 − layer_height, at least 0
/// (exclusive).
coord_um bottomPlane(const std::vector<LayerZ>& layers, std::size_t i, SlicingTolerance tolerance) {
    if (i > 0 || tolerance == SlicingTolerance::Inclusive || layers.size() < 2)
        return layers[i].bottom_z;
    const coord_um step = layers[1].print_z - layers[0].print_z;
    return std::max<coord_um>(0, layers[0].print_z - step);
}

/// Middle: the slab's middle. Inclusive / exclusive: the planes under and over the slab (CuraEngine:
/// each layer's own cut combined with the next layer's); the last layer is its own cut alone
/// (inclusive) or empty (exclusive). Every cut is taken just below its plane.
CutPlan planCuts(const std::vector<LayerZ>& layers, SlicingTolerance tolerance) {
    CutPlan plan;
    for (std::size_t i = 0; i < layers.size(); ++i) {
        if (tolerance == SlicingTolerance::Middle) {
            plan.plane_z.push_back(layers[i].slice_z);
        } else {
            plan.plane_z.push_back(layers[i].print_z);
            plan.plane_z.push_back(bottomPlane(layers, i, tolerance));
        }
    }
    std::sort(plan.plane_z.begin(), plan.plane_z.end());
    plan.plane_z.erase(std::unique(plan.plane_z.begin(), plan.plane_z.end()), plan.plane_z.end());
    const OnPlaneRule below = OnPlaneRule::CountAsAbove;
    for (std::size_t i = 0; i < layers.size(); ++i) {
        std::vector<Cut> cuts;
        if (tolerance == SlicingTolerance::Middle) {
            cuts.push_back({planeIndex(plan.plane_z, layers[i].slice_z), below});
        } else if (i + 1 < layers.size()) {
            cuts.push_back({planeIndex(plan.plane_z, layers[i].print_z), below});
            cuts.push_back({planeIndex(plan.plane_z, bottomPlane(layers, i, tolerance)), below});
        } else if (tolerance == SlicingTolerance::Inclusive) {
            cuts.push_back({planeIndex(plan.plane_z, bottomPlane(layers, i, tolerance)), below});
        }
        plan.layer_cuts.push_back(std::move(cuts));
    }
    return plan;
}

/// Inclusive: union of the two cuts; exclusive: their intersection.
Paths combineCuts(const Paths& top, const Paths& bottom, SlicingTolerance tolerance) {
    const ClipOp op = tolerance == SlicingTolerance::Inclusive ? ClipOp::Union : ClipOp::Intersection;
    return clipAreas(top, bottom, op, FillRule::Positive);
}

/// Reports progress every ~2 % of the layers, in order, from any thread.
class ProgressReporter {
  public:
    ProgressReporter(Log& log, std::size_t total)
        : log_(log), total_(total), step_(std::max<std::size_t>(1, total / 50)) {}
    void layerDone() {
        std::lock_guard lock(mutex_);
        ++done_;
        if (done_ % step_ == 0 || done_ == total_)
            log_.progress(ProgressStage::Slicing, static_cast<double>(done_) / total_);
    }

  private:
    Log& log_;
    std::size_t total_;
    std::size_t step_;
    std::size_t done_ = 0;
    std::mutex mutex_;
};

/// How many layers have a count, their sum, and the first such layer's z.
struct LayerCounts {
    std::size_t layers = 0;
    std::size_t total = 0;
    coord_um first_z = 0;

    void add(std::size_t count, coord_um z) {
        if (count == 0)
            return;
        if (layers++ == 0)
            first_z = z;
        total += count;
    }
    std::string text(const std::string& what) const {
        return std::to_string(total) + " " + what + " in " + std::to_string(layers) +
               " layers (first at z = " + std::to_string(micronsToMm(first_z)) + " mm)";
    }
};

/// One warning for a mesh that is not closed: the outlines closed across gaps (SliceOptions::max_gap_um;
/// the print may differ from what its author meant there) and the open pieces left out.
void reportOpenMesh(const std::vector<std::size_t>& gap_loops, const std::vector<SlicedLayer>& result,
                    const Mesh& mesh, Log& log) {
    LayerCounts closed, open;
    for (std::size_t i = 0; i < result.size(); ++i) {
        closed.add(gap_loops[i], result[i].print_z);
        open.add(result[i].open_polylines.size(), result[i].print_z);
    }
    std::string parts;
    if (closed.layers > 0)
        parts = closed.text("outlines closed across gaps");
    if (open.layers > 0)
        parts += (parts.empty() ? "" : "; ") + open.text("open outline pieces left out");
    if (!parts.empty())
        log.warning("mesh '" + mesh.name + "' is not closed: " + parts);
}

}  // namespace

std::vector<SlicedLayer> sliceMesh(const Mesh& mesh, const std::vector<LayerZ>& layers,
                                   const SliceOptions& options, Log& log) {
    validateMeshForSlicing(mesh);
    const CutPlan plan = planCuts(layers, options.tolerance);
    const FacetBuckets buckets(mesh, plan.plane_z);
    std::vector<SlicedLayer> result(layers.size());
    ProgressReporter progress(log, layers.size());
    std::atomic<std::size_t> segments{0};
    std::vector<std::size_t> gap_loops(layers.size(), 0);
    parallelFor(layers.size(), options.threads, [&](std::size_t i) {
        PlaneCutter cutter;  // per layer: its buffers are small next to the layer's work
        SlicedLayer& out = result[i];
        out.print_z = layers[i].print_z;
        out.slice_z = layers[i].slice_z;
        std::vector<Paths> cuts;
        for (const Cut& cut : plan.layer_cuts[i]) {
            cuts.push_back(cutter.cut(mesh, buckets.facetsAt(cut.plane), plan.plane_z[cut.plane], cut.rule,
                                      options, out.open_polylines));
        }
        if (cuts.size() == 1)
            out.outlines = std::move(cuts[0]);
        else if (cuts.size() == 2)
            out.outlines = combineCuts(cuts[0], cuts[1], options.tolerance);
        segments += cutter.segmentCount();
        gap_loops[i] = cutter.gapClosedLoops();
        progress.layerDone();
    });
    log.info("sliced '" + mesh.name + "': " + std::to_string(layers.size()) + " layers, " +
             std::to_string(mesh.faces.size()) + " facets, " + std::to_string(segments.load()) + " segments");
    reportOpenMesh(gap_loops, result, mesh, log);
    return result;
}

SlicedLayer slicePlane(const Mesh& mesh, coord_um z, const SliceOptions& options) {
    validateMeshForSlicing(mesh);
    std::vector<std::uint32_t> all_facets(mesh.faces.size());
    for (std::size_t f = 0; f < all_facets.size(); ++f)
        all_facets[f] = static_cast<std::uint32_t>(f);
    SlicedLayer layer;
    layer.print_z = z;
    layer.slice_z = z;
    PlaneCutter cutter;
    layer.outlines =
        cutter.cut(mesh, all_facets, z, OnPlaneRule::CountAsAbove, options, layer.open_polylines);
    return layer;
}

}  // namespace mixengine
