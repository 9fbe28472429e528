#pragma once
// connect_infill_polygons / connect_skin_polygons: closed infill loops that lie side by side joined
// into fewer loops, as CuraEngine 4.13 does for the polygons of its infill (concentric, cross, infill
// walls) when the setting is on:
//   - loops shorter than two line widths are dropped;
//   - taking the loops from the last one, a loop is joined to another one of those left when a point
//     of it lies between a line width (less 10 µm) and one and a half line widths from that loop and
//     a second point one line width further along it (either way round) also lies within one and a
//     half line widths of it: the stretch between the two points is cut out of both loops and the
//     two bridges between them close one loop; the joined loop takes the other's place and may be
//     joined again; a loop that joins none is kept as it is.
#include "geometry/Point.h"

namespace mixengine {

/// `loops` (closed, any orientation) joined as above for lines `line_width_um` wide.
Paths connectLoops(const Paths& loops, coord_um line_width_um);

}  // namespace mixengine
