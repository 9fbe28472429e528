#pragma once
// One extrusion axis (E, or a second mixing axis) and how the firmware reads its words.
//
// Absolute mode (M82): words carry the running position; the writer resets it with `G92 E0` at
// layer changes (resetNeeded()), so a position never exceeds one layer's filament plus one
// retraction — small enough that a 32-bit float in the firmware keeps 1e-4 mm resolution (seed 004).
// Relative mode (M83): words carry the per-move delta. Both give the same total filament.
#include <string>

namespace mixengine {

class ExtrusionAxis {
  public:
    ExtrusionAxis(char letter, bool relative) : letter_(letter), relative_(relative) {}

    char letter() const { return letter_; }
    bool relative() const { return relative_; }

    /// Moves the axis by `delta_mm` and returns the word to write, e.g. "E12.34567".
    std::string move(double delta_mm);
    /// Absolute mode: sets the position to 0 and returns "G92 E0"; relative mode: returns "".
    std::string reset();
    /// True when an absolute position is non-zero (a reset is worthwhile).
    bool resetNeeded() const { return !relative_ && position_mm_ != 0.0; }

    double position() const { return position_mm_; }
    double totalExtrudedMm() const { return total_mm_; }  ///< forward motion only, retractions excluded

  private:
    char letter_;
    bool relative_;
    double position_mm_ = 0;  ///< firmware's idea of the position (absolute mode)
    double written_mm_ = 0;   ///< rounded value last written, so rounding never accumulates
    double total_mm_ = 0;
    double retracted_mm_ = 0;  ///< outstanding retraction, re-primed moves are not new filament
};

}  // namespace mixengine
