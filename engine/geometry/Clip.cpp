#include "geometry/Clip.h"

namespace mixengine {
namespace {

ClipperLib::ClipType clipperOp(ClipOp op) {
    switch (op) {
        case ClipOp::Union:
            return ClipperLib::ctUnion;
        case ClipOp::Intersection:
            return ClipperLib::ctIntersection;
        case ClipOp::Difference:
            return ClipperLib::ctDifference;
    }
    return ClipperLib::ctUnion;
}

ClipperLib::PolyFillType clipperFill(FillRule fill) {
    switch (fill) {
        case FillRule::EvenOdd:
            return ClipperLib::pftEvenOdd;
        case FillRule::NonZero:
            return ClipperLib::pftNonZero;
        case FillRule::Positive:
            return ClipperLib::pftPositive;
    }
    return ClipperLib::pftNonZero;
}

}  // namespace

Paths clipAreas(const Paths& subject, const Paths& clip, ClipOp op, FillRule fill) {
    ClipperLib::Clipper clipper;
    clipper.AddPaths(subject, ClipperLib::ptSubject, true);
    clipper.AddPaths(clip, ClipperLib::ptClip, true);
    Paths result;
    clipper.Execute(clipperOp(op), result, clipperFill(fill), clipperFill(fill));
    return result;
}

Paths offsetMitred(const Paths& paths, double delta_um, OffsetEnds ends, double miter_limit,
                   double arc_tolerance_um) {
    ClipperLib::ClipperOffset offset(miter_limit, arc_tolerance_um);
    offset.AddPaths(paths, ClipperLib::jtMiter,
                    ends == OffsetEnds::OpenSquare ? ClipperLib::etOpenSquare : ClipperLib::etClosedPolygon);
    Paths result;
    offset.Execute(result, delta_um);
    return result;
}

bool counterClockwise(const Path& loop) {
    return ClipperLib::Orientation(loop);
}

double signedAreaUm2(const Path& loop) {
    return ClipperLib::Area(loop);
}

int pointInLoop(Point2 p, const Path& loop) {
    return ClipperLib::PointInPolygon(p, loop);
}

void reverseLoop(Path& loop) {
    ClipperLib::ReversePath(loop);
}

}  // namespace mixengine
