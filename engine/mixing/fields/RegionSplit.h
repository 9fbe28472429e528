#pragma once
// Moves that cross regions (mixing/fields/RegionField.h: painted regions, gradient bands) are cut where the
// region changes, so that each piece can carry its region's mix. Every extrusion of a painted mesh is sampled
// every 0.2 mm at the middle of its layer's height; between two samples of different regions the boundary is
// found by bisection to 5 µm, and the extrusion is cut there into pieces that keep its speed, feature and
// settings, their volume in proportion to their length.
#include <vector>

#include "mixing/fields/RegionField.h"
#include "planning/LayerPlan.h"

namespace mixengine {

/// What the splitter needs of one mesh: its regions (null: not painted) and how far the printed
/// layers are lifted above the mesh's own frame (the raft).
struct PaintedMesh {
    const RegionField* regions = nullptr;
    coord_um lift_um = 0;
};

/// Splits the plan's extrusions of painted meshes (index = PlanStep::mesh_index) at region changes.
/// Returns, per layer and step, the region of each extrusion (−1: none, also for non-extrusions,
/// raft features and extrusions of meshes without regions).
std::vector<std::vector<int>> splitAtRegions(PrintPlan& plan, const std::vector<PaintedMesh>& meshes);

}  // namespace mixengine
