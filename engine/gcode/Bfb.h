#pragma once
// Bits From Bytes machines (machine_gcode_flavor BFB), written as CuraEngine 4.13 writes them: the
// extruder motor runs at a speed in RPM instead of following E words, and the firmware retracts by
// itself when the motor stops.
//   - every move is "G1 X.. Y.. Z.. F.." (Z and F always; F in mm/min with at most one decimal);
//   - the first extruding move after the motor stopped sets its speed, "M108 S<rpm>" (one decimal,
//     only when it differs from the last one set), and starts it: "M101" (extruder n: M<(n+1)·100+1>);
//     rpm = filament mm per mm of line × feedrate in mm/min ÷ 4 (4 mm of filament per revolution),
//     and the move's feedrate is scaled by rpm ÷ (rpm rounded to 0.01), in float, as CuraEngine;
//   - the first travel after extruding stops it ("M103");
//   - the start code is followed by "M227 S<n> P<n>" (auto-retraction, n = retraction_amount in µm
//     × 2560 / 1000), and the prime before the last move onto an outer wall is "G11";
//   - every line the engine writes ends in "\r\n"; the user's start and end code keep their own
//     line ends inside (withBfbLineEnds).
#include <string>
#include <vector>

#include "geometry/Point.h"

namespace mixengine {

class BfbMotor {
  public:
    /// Lines (each ending in '\n') to write before an extruding move of `filament_mm_per_mm` at
    /// `speed_mm_s` with extruder `extruder`, appended to `lines`; returns the move's feedrate
    /// (mm/min) to write.
    double extrude(double filament_mm_per_mm, double speed_mm_s, int extruder, std::string& lines);
    /// "M103\n" when the motor runs (it stops), "" otherwise.
    std::string stop();
    /// The firmware prime before the last move onto an outer wall: "G11\n" when the motor is
    /// stopped (it then counts as running, as in CuraEngine), "" otherwise.
    std::string prime();

  private:
    bool stopped_ = false;
    float rpm_set_ = -1;  ///< the last M108 value
};

/// "G1 X<x> Y<y> Z<z> F<feedrate>" (millimetres, the feedrate in mm/min).
std::string bfbMove(const Point2& xy_um, coord_um z_um, double feedrate_mm_min);

/// The lines after the start code: ";enable auto-retraction", "M227 S<n> P<n>" and, when
/// retraction is on, "G92 E0" again (CuraEngine's reset before its first retraction).
std::string bfbAutoRetraction(coord_um retraction_amount_um, bool retraction_enable);

/// `text` with every '\n' written as "\r\n", except those inside the `verbatim` blocks (the user's
/// start and end code, each left as it is wherever it occurs).
std::string withBfbLineEnds(const std::string& text, const std::vector<std::string>& verbatim);

}  // namespace mixengine
