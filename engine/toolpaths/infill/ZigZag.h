#pragma once
// Zigzag: the lines of LineInfill (same angle, spacing and grid) joined along the area's boundary
// into long polylines, as CuraEngine's zigzag connects them.
//
// In the frame where the lines are vertical, every boundary polygon is cut by the scanlines
// x = shift + k·d; inside the area the crossings of one scanline pair up (even-odd) into the line
// segments. Walking each boundary polygon in its own direction, the boundary piece between two
// consecutive crossings is kept when it starts on an even scanline and ends on a neighbouring one,
// which alternates the connections at both ends of the lines. Segments and kept pieces share their
// end points exactly and are chained into polylines. With end pieces (`ends` not None: CuraEngine
// 4.13's use_endpieces, on for support) the boundary pieces that leave a scanline and come back to it
// — the ends of the area beyond the outermost lines, notches — and the polygons no scanline crosses
// (whole, from their last vertex round to it) are printed too, as separate polylines; Open (its ends
// not connected: support without support_connect_zigzags, the interfaces) leaves out the last line
// of each, Connected prints it.
// `zag_skip_count` N > 0 (support_skip_some_zags with support_zag_skip_count) leaves out every N-th
// connection, as CuraEngine: one from scanline s to s + 1 when s is a multiple of N, one from s to
// s − 1 when s − 1 is, so the support breaks off in pieces N lines wide.
#include "geometry/Point.h"

namespace mixengine {

enum class ZigzagEnds { None, Open, Connected };

Paths zigzagLines(const Paths& area, coord_um line_distance_um, double angle_degrees, coord_um shift_um,
                  ZigzagEnds ends, int zag_skip_count = 0);

}  // namespace mixengine
