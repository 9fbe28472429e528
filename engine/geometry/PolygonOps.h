#pragma once
// Area operations on closed polygons in microns (Clipper, non-zero fill), shared by the toolpath
// generators. Areas follow geometry/Point.h: outer contours counter-clockwise, holes clockwise.
// Loops that lie side by side are run apart (geometry/SideBySide.h): the same area, not always
// Clipper's vertex order; geometry/Clip.h has the single Clipper passes.
#include <vector>

#include "geometry/Point.h"

namespace mixengine {

/// Offset with round joins (arc tolerance 10 µm); negative = inwards. Used where CuraEngine's
/// lines are round: skirt, brim, support distances, ooze shield.
Paths offsetPolygons(const Paths& polygons, coord_um delta_um);

/// What is known of an area's loops. `United`: they are as a Clipper union, difference,
/// intersection or offset with non-zero (or positive) fill returned them and unedited since (not
/// simplified): no overlaps, no crossings, holes clockwise, so uniting them again changes nothing.
enum class Loops { Any, United };

/// Offset with mitred joins as CuraEngine 4.13 offsets its walls, skin and infill areas: the
/// polygons are united first (so a zero-width bridge left by an earlier inset is gone; left out
/// for Loops::United input, which that union would return as it is), the miter limit is 1.2 ×
/// delta (corners sharper than about 113° are squared off).
Paths offsetMiter(const Paths& polygons, coord_um delta_um, Loops loops = Loops::Any);
/// The same with another miter limit (CuraEngine's Polygons::offset uses 1.2: corners sharper than
/// about 113° are bevelled).
Paths offsetMiter(const Paths& polygons, coord_um delta_um, double miter_limit);

/// Offset with squared joins (Clipper's jtSquare, as CuraEngine 4.13's Polygons::offset(d, jtSquare)):
/// every convex corner is cut off square, d from the corner along its bisector.
Paths offsetSquare(const Paths& polygons, coord_um delta_um);

/// Removes the parts narrower than 2·radius (erode, then grow back with mitred joins), so the
/// corners of what is left stay as they were. The erosion unites `polygons` unless Loops::United;
/// the growth always unites the erosion's output, as CuraEngine 4.13's offset does: loops of it that
/// touch at a vertex become one there (skipping that union moves gap lines on armadillo52k).
Paths openPolygons(const Paths& polygons, coord_um radius_um, Loops loops = Loops::Any);

Paths unionOf(const Paths& polygons);
Paths unionOf(const Paths& a, const Paths& b);
/// a ∪ b for Clipper results: when one is empty, the other as it is, with no union pass. Such a pass
/// would only re-normalise it — except that loops of a difference's output touching at a vertex
/// would become one there; where that matters (it moves the lines filled in), use unionOf.
Paths unionOfUnited(const Paths& a, const Paths& b);
Paths intersectAll(const Paths& a, const Paths& b);
Paths differenceOf(const Paths& a, const Paths& b);

/// Removes vertices closer than `tolerance_um` to a neighbour or to the line through their
/// neighbours (Clipper's CleanPolygons); loops that degenerate disappear.
Paths cleanPolygons(const Paths& polygons, coord_um tolerance_um);

/// Open polylines clipped to the area (the pieces inside it).
Paths clipLines(const Paths& lines, const Paths& area);

/// Signed total area in µm² (holes count negative).
double areaUm2(const Paths& polygons);

/// The islands of an area: each outer contour with the holes directly inside it.
std::vector<Paths> splitIslands(const Paths& polygons);

/// Drops islands whose area (holes subtracted) is below `min_area_um2`.
Paths removeSmallIslands(const Paths& polygons, double min_area_um2);
/// CuraEngine 4.13's small-area removal (Polygons::removeSmallAreas keeping holes): the outer contours
/// whose own area (holes not taken off) is under `min_area_um2` go, with the small holes whose first
/// vertex lies in (or on) one of them; every other loop stays, in its order. A thin ring (a large
/// contour round a large hole) stays.
Paths removeSmallOutlines(const Paths& polygons, double min_area_um2);
/// removeSmallIslands(differenceOf(a, b), min_area_um2) in one Clipper pass.
Paths differenceWithoutSmallIslands(const Paths& a, const Paths& b, double min_area_um2);

/// Axis-aligned bounds; empty input gives an all-zero rectangle.
Box2 boundsOf(const Paths& polygons);

/// Total length of the polylines, closed ones including the closing segment.
double lengthUm(const Path& path, bool closed);

}  // namespace mixengine
