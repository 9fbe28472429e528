#pragma once
// Closes small gaps between open chains of cut segments (holes in a mesh, rounding leftovers).
//
// Contract: end points of different chains, or the two ends of one chain, that lie within
// max_gap_um of each other are joined, nearest pairs first (ties broken by input order, so the
// result is deterministic); each end is joined at most once and chains may be reversed to fit.
// Chains that become closed are appended to `loops` (first point not repeated); the others,
// joined where possible, replace the contents of `open_pieces`. Candidate pairs are found with a
// sweep over the ends sorted by x, O(k log k) for k chains plus the pairs within the gap.
#include <vector>

#include "slicing/SegmentStitcher.h"

namespace mixengine {

void closeGaps(std::vector<StitchedPath>& open_pieces, coord_um max_gap_um, std::vector<StitchedPath>& loops);

}  // namespace mixengine
