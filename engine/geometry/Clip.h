#pragma once
// Single Clipper passes, exactly as asked, and the loop queries the engine needs (the Clipper facade:
// with geometry/PolygonOps.h the only way the engine reaches Clipper; no other folder names it).
// Everything is in integer microns (geometry/Point.h); areas follow its convention, outer contours
// counter-clockwise and holes clockwise. Unlike PolygonOps.h, nothing here splits the input into
// side-by-side groups: each call is one Clipper run over the whole input, in the order given, so its
// result is Clipper's own, vertex for vertex.
#include "geometry/Point.h"

namespace mixengine {

/// The boolean operation of clipAreas.
enum class ClipOp { Union, Intersection, Difference };

/// Which points an area of loops covers (Clipper's fill types), counting the loops around a point
/// (counter-clockwise +1, clockwise −1): EvenOdd — an odd number of loops; NonZero — a winding number
/// other than 0; Positive — a winding number above 0.
enum class FillRule { EvenOdd, NonZero, Positive };

/// One Clipper pass over closed loops: `subject` op `clip`, both read with `fill`. The loops of
/// `subject` are added first, in order, then those of `clip` (an empty `clip` adds nothing: a union of
/// `subject` alone). Returns the result's loops as Clipper orders them (no overlaps, holes clockwise).
Paths clipAreas(const Paths& subject, const Paths& clip, ClipOp op, FillRule fill);

/// What an offset does at the ends of a path: ClosedPolygon — the path is a loop (grows outwards for
/// delta > 0 on a counter-clockwise loop, inwards for delta < 0); OpenSquare — the path is an open
/// polyline turned into a band 2·delta wide, with square ends reaching delta beyond its end points.
enum class OffsetEnds { ClosedPolygon, OpenSquare };

/// One Clipper offset pass with mitred joins: `paths` moved by `delta_um` (microns; a fraction is kept
/// as Clipper takes it), corners sharper than the miter limit (× delta) squared off, round ends and
/// arcs within `arc_tolerance_um`. Returns what Clipper returns (united loops).
Paths offsetMitred(const Paths& paths, double delta_um, OffsetEnds ends, double miter_limit,
                   double arc_tolerance_um);

/// Whether `loop` runs counter-clockwise, i.e. its signed area is >= 0 (Clipper's Orientation): an
/// outer contour, where clockwise is a hole.
bool counterClockwise(const Path& loop);

/// The signed area enclosed by `loop` in µm² (> 0 counter-clockwise, < 0 clockwise; Clipper's Area).
double signedAreaUm2(const Path& loop);

/// Where `p` lies against the closed `loop` (either orientation; Clipper's PointInPolygon): 1 inside,
/// 0 outside, −1 on its edge.
int pointInLoop(Point2 p, const Path& loop);

/// Reverses the order of the loop's vertices in place (so its orientation).
void reverseLoop(Path& loop);

}  // namespace mixengine
