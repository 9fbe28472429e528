#pragma once
// How a firmware is told the amount of filament per move and the mix (architecture: "a dialect
// object turns that into G-code"). GCodeExport owns one dialect and asks it for the extrusion
// words of every extruding move, retraction and prime, and for the reset line at layer starts.
//
//   single mode      one E axis, exactly the single-colour output (gcode/format/ExtrusionAxis.h)
//   eb_axes          E and B words on every move (MakerPi: M82/M83 and G92 act on both)
//   klipper_b        E as usual, B on a Klipper manual_stepper: always absolute, never G92-reset
//   rrf_colon        `E<a>:<b>` words, relative extrusion only (M83 forced)
//   marlin_m163      total E; `M163 S<i> P<f>` … `M164 S<tool>` when the quantised mix changes
//   marlin_m165      total E; `M165 A<f> B<f> …` when the quantised mix changes
//   rrf_m567         total E; `M567 P<tool> E<a>:<b>` when the quantised mix changes
//
// In every dialect the channel amounts of one move add up exactly (in written units of 1e-5) to
// the E word the single-colour output would have for that move.
#include <memory>
#include <string>
#include <vector>

#include "mixing/setup/MixingOutput.h"
#include "planning/MixVector.h"

namespace mixengine {

class MixDialect {
  public:
    virtual ~MixDialect() = default;

    /// Words for a move extruding `amount` in total (axis unit: mm of filament, or mm³ when
    /// volumetric) with `mix`, e.g. "E1.2 B0.3". Lines that must come before the move (mix
    /// commands, mode switches), each ending in '\n', are appended to `before`.
    virtual std::string extrude(double amount, const MixVector& mix, std::string& before) = 0;
    /// Words retracting `amount` (> 0) with the last mix; prime() puts back what it took.
    virtual std::string retract(double amount, std::string& before) = 0;
    virtual std::string prime(double amount, std::string& before) = 0;
    /// The line resetting absolute positions at a layer start ("G92 E0", "G92 E0 B0"), or "".
    virtual std::string reset() = 0;
    /// The letter of the (total) extrusion axis: E, or MACH3's A, B, ... per extruder. The split-axis
    /// mixing dialects keep their own letters.
    virtual void setAxisLetter(char /*letter*/) {}
    /// Forward filament of all channels together (retractions and their primes excluded).
    virtual double totalExtruded() const = 0;
    /// Forward filament per channel (one entry in single mode).
    virtual std::vector<double> channelTotals() const = 0;
};

/// The dialect of `mixing` (the single E axis when mixing is off). `relative_extrusion` is the
/// print's M83 setting.
std::unique_ptr<MixDialect> makeMixDialect(const MixingOutput& mixing, bool relative_extrusion);

}  // namespace mixengine
