#pragma once
// The lines a lightning tree (toolpaths/infill/lightning/LightningForest.h) prints, as CuraEngine
// 4.13 draws them (LightningTreeNode::convertToPolylines): polylines from each branch end up to
// the junction where the branch meets a longer one (the first child of a node continues its
// polyline; the root's polyline ends at the root), each shortened at its upper end by half a
// line width so that it does not overprint the line it meets, then cut into two-point segments
// (Cura prints them as separate lines). Lengths in microns.
#include <vector>

#include "geometry/Point.h"
#include "toolpaths/infill/lightning/LightningForest.h"

namespace mixengine {

/// One tree's lines and where its root is (a tree prints in the infill area its root lies in).
struct LightningTreeLines {
    Point2 root{0, 0};
    Paths segments;
};

/// Every tree of the forest, in the order of forest.roots.
std::vector<LightningTreeLines> treeLines(const LightningForest& forest, coord_um line_width_um);

}  // namespace mixengine
