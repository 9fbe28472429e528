#pragma once
// The order of a layer part's skin group, as CuraEngine 4.13 prints a part's skin
// (FffGcodeWriter::processSkinAndPerimeterGaps): the paths of each skin part
// (ExtrusionPath::skin_part) print together, stage by stage (ExtrusionPath::skin_stage: its loops,
// then its roofing, its skin fill, the lines filling a concentric fill's gaps), the stages each
// ordered by the planner; the lines of no skin part listed before the first skin part's (outline
// gaps) come first, those listed after it (perimeter gaps) last.
//
// The skin parts are ordered once, before any is printed, as CuraEngine orders them (a path order
// over each part's outline): from `from`, the part with a vertex nearest to the current point is
// next, and the search goes on from that vertex. A part is represented by the vertices of its loops
// (stage 1: its outline less half a line width), or by all its paths' points when it has no loops.
#include <vector>

#include "geometry/Point.h"
#include "toolpaths/core/ExtrusionPath.h"

namespace mixengine {

/// A skin part's loops (stage 1) in the order CuraEngine 4.13 prints them (LayerPlan::addWalls, its
/// path order with the shortest seam): from `from`, the loop with the vertex nearest to the current
/// point is next, and the search goes on from that vertex (where the loop starts and ends).
std::vector<ExtrusionPath> loopsNearestFirst(std::vector<ExtrusionPath> loops, const Point2& from);

/// `paths` (one part's skin group, in the toolpaths' order) split into the groups printed one after
/// the other, as above; empty groups are left out.
std::vector<std::vector<ExtrusionPath>> skinPrintGroups(std::vector<ExtrusionPath> paths, const Point2& from);

}  // namespace mixengine
