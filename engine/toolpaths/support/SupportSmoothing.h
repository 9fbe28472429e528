#pragma once
// The outward smoothing CuraEngine 4.13 gives each layer's support area after joining it with the
// layer above (AreaSupport::join, before the model is taken out): the unions of the overhangs of
// consecutive layers leave sharp notches in the area's outline, and each notch sharper than
// `max_angle_degrees` (135°: a corner of the area's outside narrower than that) is filled with a
// straight shortcut `shortcut_um` long (the widest of the support, roof and floor lines):
//   - the shortcut's ends lie at equal distances from the notch's corner on its two edges;
//   - when one edge is too short for that, the shortcut starts at that edge's far end and ends on
//     the other edge, `shortcut_um` away (or at its far end, if that is nearer);
//   - when the two edges' far ends are closer than `shortcut_um`, the corner is simply left out.
// Only notches are changed (a corner that bends into the area: outer loops and holes alike); points
// closer than 10 µm to the one before are dropped first; each corner is looked at once, in the loop's
// order, against the corner before it as already smoothed; a loop left with fewer than three points
// is dropped.
#include "geometry/Point.h"

namespace mixengine {

Paths smoothOutward(const Paths& areas, double max_angle_degrees, coord_um shortcut_um);

}  // namespace mixengine
