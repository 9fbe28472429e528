#pragma once
// How a lightning tree (toolpaths/infill/lightning/LightningForest.h) is carried one layer down,
// as CuraEngine 4.13 carries it (LightningTreeNode::propagateToNextLayer): a copy of it is
//   pruned      — every branch end drawn back along its branch by `prune_um` (branches shorter
//                 than that disappear), so a tree shrinks as it goes down;
//   straightened — each run of nodes between two junctions (or a junction and an end) moves
//                 towards the straight line between them by at most `straighten_um` per node, and
//                 a junction that is not the root towards the mean direction of its branches by
//                 at most ¾ of it (not when one of its branches is shorter than `straighten_um`);
//                 a node within 10 µm² of the line between its neighbours, those being less than
//                 `colinear_um` apart, is dropped;
//   realigned   — to the layer below's outline: the part of the tree outside it is cut away (the
//                 branches that come back inside become trees of their own, remembering the
//                 node they hung from), and a branch that crosses the outline within
//                 `crossing_reach_um` of its upper end is cut off as a tree of its own (nothing
//                 remembered, and its parent forgets its own grounding).
// Lengths in microns.
#include <vector>

#include "geometry/Point.h"
#include "toolpaths/infill/lightning/LightningForest.h"
#include "toolpaths/infill/lightning/OutlineGrid.h"

namespace mixengine {

struct PropagationParams {
    coord_um prune_um = 0;
    coord_um straighten_um = 0;
    coord_um colinear_um = 2'000;
    coord_um crossing_reach_um = 8'000;
};

/// The tree under `root` of `above`, carried into `below` (whose outline is `outlines`, with its
/// grid `grid`): the trees it leaves are appended to below.roots (the pieces cut off first, then
/// the tree itself when its root is inside the outline).
void propagateTree(const LightningForest& above, int root, const Paths& outlines, const OutlineGrid& grid,
                   const PropagationParams& params, LightningForest& below);

/// The pruning alone (see above) of the tree under `root`; the length drawn back at most.
coord_um pruneTree(LightningForest& forest, int root, coord_um prune_um);

/// The straightening alone (see above) of the tree under `root`.
void straightenTree(LightningForest& forest, int root, coord_um straighten_um, coord_um colinear_um);

}  // namespace mixengine
