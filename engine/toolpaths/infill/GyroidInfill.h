#pragma once
// Gyroid infill: the section at height z of the gyroid surface
//   sin(X)·cos(Y) + sin(Y)·cos(Z) + sin(Z)·cos(X) = 0,   (X, Y, Z) = 2π·(x, y, z) / period,
// as polylines clipped to an area. Per layer the curve is solved exactly for Y as a function of
// X where |cos Z| ≥ |sin Z| and for X as a function of Y elsewhere, so the two families of curves
// never break up; X (or Y) is sampled every period / 16.
//
// period = 2.41 × infill_line_distance, as CuraEngine: the section then has about the length per
// area of lines at infill_line_distance (two curves per period in each direction).
#include "geometry/Point.h"

namespace mixengine {

constexpr double kGyroidPeriodPerLineDistance = 2.41;

Paths gyroidCurves(const Paths& area, coord_um period_um, coord_um z_um);

}  // namespace mixengine
