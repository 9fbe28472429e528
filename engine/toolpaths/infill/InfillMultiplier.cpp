#include "toolpaths/infill/InfillMultiplier.h"

#include "geometry/Clip.h"
#include "geometry/PolygonOps.h"

namespace mixengine {
namespace {

constexpr double kMiterLimit = 1.2;  // as CuraEngine's offsets

Paths offsetWith(const Paths& paths, coord_um delta, OffsetEnds ends) {
    if (paths.empty())
        return {};
    return offsetMitred(paths, static_cast<double>(delta), ends, kMiterLimit, 10.0);
}

Paths evenOddAreas(const Paths& loops) {
    return clipAreas(loops, {}, ClipOp::Union, FillRule::EvenOdd);
}

/// Even-odd intersection: nested loops keep every boundary (CuraEngine's default fill rule).
Paths intersectEvenOdd(const Paths& loops, const Paths& outline) {
    return clipAreas(loops, outline, ClipOp::Intersection, FillRule::EvenOdd);
}

/// The bands around the lines and rings along the loops, `offset` to each side.
Paths firstOffset(const Paths& lines, const Paths& loops, coord_um offset) {
    const Paths bands = offsetWith(lines, offset, OffsetEnds::OpenSquare);
    const Paths rings = differenceOf(offsetWith(loops, offset, OffsetEnds::ClosedPolygon),
                                     offsetWith(loops, -offset, OffsetEnds::ClosedPolygon));
    return unionOf(bands, rings);
}

/// Closed loops cut by the outline into open polylines (CuraEngine cuts them further into two-point
/// lines, which its line order optimizer chains again; the pieces are kept whole here).
Paths cutOpen(const Paths& loops, const Paths& outline) {
    Paths polylines;
    for (const Path& loop : loops) {
        if (loop.empty())
            continue;
        Path closed = loop;
        closed.push_back(loop.front());
        polylines.push_back(std::move(closed));
    }
    return clipLines(polylines, outline);
}

}  // namespace

void multiplyInfill(Paths& lines, Paths& loops, const Paths& outline, const MultiplyParams& p) {
    if (p.multiplier <= 1)
        return;
    if (p.loops_are_rings)
        loops = evenOddAreas(loops);
    const bool odd = p.multiplier % 2 == 1;
    const coord_um w = p.line_width_um;
    Paths first = firstOffset(lines, loops, odd ? w : w / 2);
    if (p.connected)
        first = differenceOf(outline, first);
    Paths result = first;
    Paths reference = first;
    for (int pair = 1; pair < p.multiplier / 2; ++pair) {
        reference = offsetWith(reference, p.connected ? -w : w, OffsetEnds::ClosedPolygon);
        result.insert(result.end(), reference.begin(), reference.end());
    }
    if (p.connected)
        result = intersectEvenOdd(result, outline);
    if (!odd) {
        lines.clear();
        loops.clear();
    }
    loops.insert(loops.end(), result.begin(), result.end());
    if (p.connected)
        return;
    const Paths cut = cutOpen(loops, outline);
    lines.insert(lines.end(), cut.begin(), cut.end());
    loops.clear();
}

}  // namespace mixengine
