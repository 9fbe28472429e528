#pragma once
// The acceleration and jerk commands CuraEngine 4.13 writes when acceleration_enabled /
// jerk_enabled is on, in the forms of the firmware flavor (gcode/Flavor.h), each only when its
// value changes:
//   Marlin and the rest   M204 S<a> (one acceleration for print and travel), M205 X<j> Y<j>
//   RepRap (RepRap)       M204 P<a> (print) / M204 T<a> (travel), M566 X<j·60> Y<j·60> (mm/min)
//   Repetier              M201 X<a> Y<a> (print) / M202 X<a> Y<a> (travel), M207 X<j>
// Accelerations are written as whole numbers, jerks with up to two decimals.
#include <string>
#include <vector>

#include "gcode/Flavor.h"

namespace mixengine {

class MotionCommands {
  public:
    explicit MotionCommands(const MotionForms& forms = flavorTraits(Flavor::Marlin).motion) : forms_(forms) {}

    /// The lines for a move with this acceleration (mm/s², 0 = none) as print or travel move.
    std::vector<std::string> acceleration(double mm_s2, bool travel);
    /// The lines for a move with this XY jerk (mm/s, 0 = none).
    std::vector<std::string> jerk(double mm_s);

  private:
    MotionForms forms_;
    double print_mm_s2_ = -1;
    double travel_mm_s2_ = -1;
    double jerk_mm_s_ = -1;
};

}  // namespace mixengine
