#pragma once
// The frame in which infill lines at an angle are vertical, shared by line and zig-zag infill
// (angle convention in toolpaths/infill/LineInfill.h): an area is rotated by +angle into it, the lines
// found there are rotated by −angle back; each point is rounded to whole microns each way. In the
// frame the lines lie on the grid x = phase + k·spacing for every integer k.
#include "geometry/Point.h"

namespace mixengine {

class LineFrame {
  public:
    explicit LineFrame(double angle_degrees);

    /// `area` rotated into the frame (by +angle).
    Paths into(Paths area) const;
    /// Rotates `lines` found in the frame back (by −angle), in place.
    void back(Paths& lines) const;

  private:
    double cos_a_;
    double sin_a_;
};

/// a / b rounded towards −∞ (b ≠ 0).
coord_um floorDiv(coord_um a, coord_um b);

/// Where the line grid of `spacing_um` shifted by `shift_um` starts: shift_um mod spacing_um, in
/// [0, spacing_um) (spacing_um > 0).
coord_um linePhase(coord_um shift_um, coord_um spacing_um);

}  // namespace mixengine
