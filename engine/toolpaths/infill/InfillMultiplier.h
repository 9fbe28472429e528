#pragma once
// Cura's infill_multiplier: every infill line printed as N parallel lines, as CuraEngine 4.13
// multiplies them (Infill::multiplyInfill):
//   - the pattern's lines are thickened into bands (square ends) and its loops into rings, at
//     offset w from them for odd N (the line itself stays in the middle) or w/2 for even N (the
//     line itself goes); the bands' edges are the first new lines, one on each side;
//   - each further pair (N > 3: N/2 − 1 more) is the previous edges offset by w once more, outwards
//     — or, with connected lines (zig_zaggify_infill), inwards into the cells between the bands,
//     the cells' outlines being the first new lines then;
//   - connected: the new lines are closed loops clipped to the outline; otherwise they are cut to
//     the outline into open polylines (and the odd N's middle loops with them; CuraEngine goes on
//     to split them into two-point lines, which its line order optimizer chains again).
// w = line_width_um; `outline` is the infill area the lines may not leave (without the overlap).
#include "geometry/Point.h"

namespace mixengine {

struct MultiplyParams {
    int multiplier = 1;
    coord_um line_width_um = 400;
    bool connected = false;        ///< zig_zaggify_infill
    bool loops_are_rings = false;  ///< concentric: the loops become rings (even-odd) before offsetting
};

/// Replaces `lines` (open) and `loops` (closed) by the multiplied pattern.
void multiplyInfill(Paths& lines, Paths& loops, const Paths& outline, const MultiplyParams& params);

}  // namespace mixengine
