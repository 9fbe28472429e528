#pragma once
// Where vertical scanlines cross the edges of polygons, shared by zigzag infill (toolpaths/infill/ZigZag.h)
// and connected infill lines (toolpaths/infill/ConnectedLines.h). Coordinates are those of the frame in
// which the lines are vertical (toolpaths/infill/LineFrame.h); scanline k is x = phase + k·spacing.
//
// An edge runs from vertex e to vertex e + 1 (the last one back to vertex 0). A point with
// x ≥ x_k counts as right of scanline k, so a vertex exactly on a scanline gives one crossing where
// the boundary passes through it and none or two where it only touches: every scanline is crossed
// an even number of times by a closed polygon. Crossings are listed per polygon in walking order
// (by edge, then along the edge), their y rounded to whole microns.
#include <vector>

#include "geometry/Point.h"

namespace mixengine {

struct ScanCrossing {
    long long line = 0;       ///< scanline number k
    Point2 point;             ///< on the scanline, in the frame
    std::size_t polygon = 0;  ///< index of the polygon
    std::size_t edge = 0;     ///< index of the edge's first vertex
    double along = 0;         ///< position along the edge, 0..1
};

std::vector<ScanCrossing> findScanCrossings(const Paths& polygons, coord_um spacing_um, coord_um phase_um);

/// The segments inside the polygons: on every scanline the crossings sorted by y pair up
/// even–odd. partner[i] is the index of the crossing paired with crossing i, −1 for none (a
/// degenerate odd count on a scanline leaves one crossing unpaired).
std::vector<long> pairOnScanlines(const std::vector<ScanCrossing>& crossings);

}  // namespace mixengine
