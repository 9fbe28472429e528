#pragma once
// The outward smoothing CuraEngine 4.13 gives each layer's support area after joining it with the
// layer above (AreaSupport::join, Polygons::smooth_outward, before the model is taken out): the
// unions of the overhangs of consecutive layers leave sharp notches in the area's outline, and each
// notch sharper than `max_angle_degrees` (135°: a corner of the area's outside narrower than that)
// is filled with a straight shortcut `shortcut_um` long (the widest of the support, roof and floor
// lines). Done as CuraEngine does it, to the micrometre (its integer vector arithmetic: truncated
// lengths, integer scaling; the corner's cosine in float from millimetres):
//   - first, walking from the loop's start, a point closer than 10 µm to the next one goes (the walk
//     ends when it comes back to the loop's start, which moves on when the start itself goes);
//   - then each corner in turn from the start, against the corners before it as already changed;
//     after a notch the walk goes on at the point after it (until it is back at the start);
//   - a notch whose neighbours lie at least `shortcut_um` apart: if they lie less than
//     shortcut_um + 10 µm apart (or the notch is a spike, its cosine over 0.9999, the next point
//     within 20 µm of the line through the other two), the corner just goes; else the shortcut's
//     ends lie at equal distances from the corner on its two edges, or when one edge is too short for
//     that, the shortcut starts at that edge's far end and ends on the other edge `shortcut_um` away;
//   - a notch whose neighbours lie closer: the shortcut's ends walk away from the corner, point by
//     point (the nearer side first), as long as the shortcut stays within `shortcut_um` and does not
//     cut into the area; then they are moved part way along their next edges so that it is
//     `shortcut_um` long (or only the free one, when the other is blocked), and the points between
//     them go; when the walk goes all the way round the loop, the loop goes.
// Only notches are changed (a corner that bends into the area: outer loops and holes alike); loops
// of fewer than three points go, loops of three are kept as they are, a loop left with fewer than
// three points is dropped. `shortcut_um` ≤ 0: nothing changes.
#include "geometry/Point.h"

namespace mixengine {

Paths smoothOutward(const Paths& areas, double max_angle_degrees, coord_um shortcut_um);

}  // namespace mixengine
