#pragma once
// How a layer's lightning trees (toolpaths/infill/lightning/LightningForest.h) grow, as CuraEngine
// 4.13's LightningLayer grows them:
//   new branches — each overhang point not yet held (toolpaths/infill/lightning/UnsupportedPoints.h)
//                  is joined to its best ground: the nearest outline point (a new tree, its
//                  root there), or a node of a tree when that is nearer by its weighted
//                  distance — the distance less 4·radius for a node with 1 to 3 links — and the
//                  straight line to it does not touch the outline; the nodes looked at are those in
//                  the cells (`node_cell_um`) that the square around the point out to the outline's
//                  distance reaches (as CuraEngine's grid: up to a cell further); trees are only
//                  looked at when the outline is at least the wall reach (`wall_reach_um`) away;
//   reconnection — each tree carried down from the layer above (`carried`, its roots in
//                  forest.roots) is held again: when its root remembers where it hung from, the
//                  tree is extended from its root towards that place up to the outline (when the
//                  outline is crossed within `crossing_reach_um` of it); otherwise it is grounded
//                  as a new branch would be (trees looked at from wall reach − 100 µm), at its
//                  node nearest to that ground: on the outline, or hung into another tree.
// Lengths in microns.
#include <vector>

#include "geometry/Point.h"
#include "toolpaths/infill/lightning/LightningForest.h"
#include "toolpaths/infill/lightning/OutlineGrid.h"
#include "toolpaths/infill/lightning/UnsupportedPoints.h"

namespace mixengine {

struct GrowthParams {
    coord_um radius_um = 0;      ///< how far a line holds up what lies above it
    coord_um wall_reach_um = 0;  ///< how far the outline holds up what lies above it
    coord_um crossing_reach_um = 8'000;
    coord_um node_cell_um = 4'000;  ///< cell of the grid the nodes are looked up in
};

/// Grows branches to every point of `unsupported`.
void growNewBranches(LightningForest& forest, UnsupportedPoints& unsupported, const OutlineGrid& outline,
                     const GrowthParams& params);

/// Grounds again the trees `carried` (roots of forest.roots, carried down from the layer above).
void reconnectCarried(LightningForest& forest, const std::vector<int>& carried, const OutlineGrid& outline,
                      const GrowthParams& params);

}  // namespace mixengine
