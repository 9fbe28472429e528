#include "mixing/fields/RegionSplit.h"
#include "geometry/Point.h"

#include <cmath>

namespace mixengine {
namespace {

constexpr double kSampleUm = 200;
constexpr double kBoundaryUm = 5;

bool isRaftFeature(Feature feature) {
    return feature == Feature::RaftBase || feature == Feature::RaftInterface ||
           feature == Feature::RaftSurface;
}

/// One straight extrusion at height z: the region at a fraction t of the way.
struct Segment {
    Point2 from, to;
    coord_um z;
    const RegionField* regions;

    Point2 at(double t) const {
        return {from.X + static_cast<coord_um>(std::llround(t * static_cast<double>(to.X - from.X))),
                from.Y + static_cast<coord_um>(std::llround(t * static_cast<double>(to.Y - from.Y)))};
    }
    int regionAt(double t) const {
        const Point2 p = at(t);
        return regions->regionAt({p.X, p.Y, z});
    }
    double lengthUm() const { return distanceUm(to, from); }
};

struct Piece {
    double end_t;
    int region;
};

/// The pieces of one segment: where the region changes, by sampling and bisection.
std::vector<Piece> piecesOf(const Segment& s) {
    const double length = s.lengthUm();
    const int samples = std::max(1, static_cast<int>(std::ceil(length / kSampleUm)));
    std::vector<Piece> pieces;
    double t0 = 0;
    int r0 = s.regionAt(0.5 / samples);  // the first sample inside the segment
    for (int i = 1; i <= samples; ++i) {
        const double t1 = (i + 0.5) / samples;
        const int r1 = i < samples ? s.regionAt(t1) : r0;
        if (r1 != r0) {
            double lo = t0 > (i - 0.5) / samples ? t0 : (i - 0.5) / samples, hi = t1;
            while ((hi - lo) * length > kBoundaryUm) {
                const double mid = (lo + hi) / 2;
                (s.regionAt(mid) == r0 ? lo : hi) = mid;
            }
            pieces.push_back({(lo + hi) / 2, r0});
            t0 = (lo + hi) / 2;
            r0 = r1;
        }
    }
    pieces.push_back({1.0, r0});
    return pieces;
}

struct LayerState {
    Point2 head{0, 0};
    int mesh = -1;
    Feature feature = Feature::Fill;
};

const PaintedMesh* paintedMeshOf(const LayerState& state, const std::vector<PaintedMesh>& meshes) {
    if (state.mesh < 0 || static_cast<std::size_t>(state.mesh) >= meshes.size() ||
        isRaftFeature(state.feature))
        return nullptr;
    const PaintedMesh& m = meshes[static_cast<std::size_t>(state.mesh)];
    return m.regions ? &m : nullptr;
}

/// Appends `step` to `out` (cut into pieces when it is an extrusion of a painted mesh).
void splitStep(const PlanStep& step, const PlannedLayer& layer, const std::vector<PaintedMesh>& meshes,
               LayerState& state, std::vector<PlanStep>& out, std::vector<int>& regions) {
    if (step.kind == PlanStep::Kind::SetMesh)
        state.mesh = step.mesh_index;
    if (step.kind == PlanStep::Kind::SetFeature)
        state.feature = step.feature;
    const PaintedMesh* painted =
        step.kind == PlanStep::Kind::Extrude ? paintedMeshOf(state, meshes) : nullptr;
    if (!painted) {
        out.push_back(step);
        regions.push_back(-1);
    } else {
        const coord_um middle =
            layer.z - (layer.thickness > 0 ? layer.thickness / 2 : 100) - painted->lift_um;
        const Segment segment{state.head, step.to, middle, painted->regions};
        double start = 0;
        for (const Piece& piece : piecesOf(segment)) {
            PlanStep part = step;
            part.to = piece.end_t >= 1.0 ? step.to : segment.at(piece.end_t);
            part.volume_mm3 = step.volume_mm3 * (piece.end_t - start);
            start = piece.end_t;
            out.push_back(part);
            regions.push_back(piece.region);
        }
    }
    const bool moves = step.kind == PlanStep::Kind::Extrude || step.kind == PlanStep::Kind::Travel ||
                       step.kind == PlanStep::Kind::LiftHead;
    if (moves)
        state.head = step.to;
}

}  // namespace

std::vector<std::vector<int>> splitAtRegions(PrintPlan& plan, const std::vector<PaintedMesh>& meshes) {
    std::vector<std::vector<int>> regions;
    LayerState state;
    for (PlannedLayer& layer : plan.layers) {
        state.mesh = -1;  // each layer names its mesh and feature again (as the mixing stage reads it)
        state.feature = Feature::Fill;
        std::vector<PlanStep> steps;
        std::vector<int> layer_regions;
        steps.reserve(layer.steps.size());
        for (const PlanStep& step : layer.steps)
            splitStep(step, layer, meshes, state, steps, layer_regions);
        layer.steps = std::move(steps);
        regions.push_back(std::move(layer_regions));
    }
    return regions;
}

}  // namespace mixengine
