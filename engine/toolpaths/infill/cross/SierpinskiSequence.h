#pragma once
// The triangles the cross fractal crosses, in curve order: a cut through the tree
// (toolpaths/infill/cross/SierpinskiTree.h) whose curve length follows the requested density, as
// CuraEngine 4.13's SierpinskiFill chooses it (with dithering and constraint error diffusion):
//   1. lower bound — starting from the root, repeatedly subdivide every triangle (shallowest first)
//      whose requested length, with the errors moved to it, covers its children's curve; a triangle
//      crossed from AC to AB and the next one, which share the side AB, subdivide together; a
//      triangle next to a shallower one across AB (constrained) does not, and passes what it lacks to
//      that neighbour instead; the errors a subdivision leaves over go back whence they came and are
//      balanced over the children so none is left short;
//   2. settle — every triangle above the deepest level hands what it holds beyond its own curve back
//      to the neighbours it came from;
//   3. dither — walking the curve, a free triangle (or pair) subdivides once more when its value plus
//      the carried error reaches halfway between its curve and its children's; the difference
//      between what it asked and what it got is carried on.
// The result is deterministic. `tree`'s errors are changed on the way.
#include <vector>

#include "toolpaths/infill/cross/SierpinskiTree.h"

namespace mixengine {

/// The node indices of the curve's triangles, from its start to its end (the root alone when the
/// tree has no depth).
std::vector<int> crossSequence(SierpinskiTree& tree);

}  // namespace mixengine
