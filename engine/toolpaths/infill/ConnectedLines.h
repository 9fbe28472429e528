#pragma once
// Infill lines joined along the edge of their area into polylines (Cura's zig_zaggify_infill for
// the line-based patterns), as CuraEngine 4.13 connects them:
//
// Every line set (spacing, angle, phase: the lines of toolpaths/infill/LineInfill.h) is cut into the
// segments inside `area`, each ending on two edges of the area's polygons. Then each polygon is
// walked from its last vertex on, edge by edge, meeting the segment ends in order along every edge:
// the first end met starts a connector; the connector follows the edge through the polygon's
// vertices to the next end whose segment is not yet joined (directly or through other connectors)
// to the starting one, and there it ends, joining the two; the next end met starts a new
// connector. Ends of segments already joined to the starting one are passed over. A connector still
// open when the walk reaches the polygon's last vertex (or that stops exactly on a vertex) stays
// attached to its starting segment as a tail along the edge. The joined segments and connectors
// form chains without loops; each chain is returned as one polyline.
//
// The caller insets the area by half a line width first (CuraEngine: the connectors lie beside the
// edge, not on it).
#include <vector>

#include "geometry/Point.h"

namespace mixengine {

/// Parallel lines at `angle_degrees` (toolpaths/infill/LineInfill.h's convention), `spacing_um` apart,
/// through x = phase_um in the frame where they are vertical.
struct LineSet {
    coord_um spacing_um = 0;
    double angle_degrees = 0;
    coord_um phase_um = 0;
};

Paths connectedLines(const Paths& area, const std::vector<LineSet>& sets);

}  // namespace mixengine
