#include "toolpaths/infill/LineFrame.h"

#include <cmath>

#include "geometry/Angles.h"

namespace mixengine {
namespace {

Point2 rotate(const Point2& p, double cos_a, double sin_a) {
    return {static_cast<coord_um>(std::llround(double(p.X) * cos_a - double(p.Y) * sin_a)),
            static_cast<coord_um>(std::llround(double(p.X) * sin_a + double(p.Y) * cos_a))};
}

void rotateAll(Paths& paths, double cos_a, double sin_a) {
    for (Path& path : paths)
        for (Point2& p : path)
            p = rotate(p, cos_a, sin_a);
}

}  // namespace

LineFrame::LineFrame(double angle_degrees)
    : cos_a_(std::cos(radiansFromDegrees(angle_degrees))),
      sin_a_(std::sin(radiansFromDegrees(angle_degrees))) {}

Paths LineFrame::into(Paths area) const {
    rotateAll(area, cos_a_, sin_a_);
    return area;
}

void LineFrame::back(Paths& lines) const {
    rotateAll(lines, cos_a_, -sin_a_);
}

coord_um floorDiv(coord_um a, coord_um b) {
    const coord_um q = a / b;
    return (a % b != 0 && (a < 0) != (b < 0)) ? q - 1 : q;
}

coord_um linePhase(coord_um shift_um, coord_um spacing_um) {
    return ((shift_um % spacing_um) + spacing_um) % spacing_um;
}

}  // namespace mixengine
