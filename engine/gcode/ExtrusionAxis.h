#pragma once
// One extrusion axis (E, or a second mixing axis) and how the firmware reads its words.
//
// Absolute mode (M82): words carry the running position; the writer resets it with `G92 E0` at
// layer changes (resetNeeded()), so a position never exceeds one layer's filament plus one
// retraction — small enough that a 32-bit float in the firmware keeps 1e-4 mm resolution (seed 004).
// Relative mode (M83): words carry the per-move delta. Both give the same total filament.
//
// Words are written with 5 decimals; a "unit" is that resolution (1e-5 mm, or mm³ when volumetric).
// moveUnits() is the integer view used by the mixing dialects (gcode/MixDialect.h): how far the
// written value moves, which is exactly what a firmware sees between two words.
#include <string>

namespace mixengine {

inline constexpr double kUnitsPerMm = 1e5;  ///< written resolution of extrusion words

/// "12.34567" for 1234567 units (no letter).
std::string formatUnits(long long units);

class ExtrusionAxis {
  public:
    ExtrusionAxis(char letter, bool relative) : letter_(letter), relative_(relative) {}

    char letter() const { return letter_; }
    bool relative() const { return relative_; }

    /// Moves the axis by `delta_mm` and returns the word to write, e.g. "E12.34567".
    std::string move(double delta_mm);
    /// Moves the axis by `delta_mm` like move() but returns, instead of a word, how many units
    /// the written value moves (absolute: new written position − old; relative: the delta word).
    long long moveUnits(double delta_mm);
    /// Absolute mode: sets the position to 0 and returns "G92 E0"; relative mode: returns "".
    std::string reset();
    /// True when an absolute position is non-zero (a reset is worthwhile).
    bool resetNeeded() const { return !relative_ && position_mm_ != 0.0; }

    double position() const { return position_mm_; }
    double totalExtrudedMm() const { return total_mm_; }  ///< forward motion only, retractions excluded

  private:
    void account(double delta_mm);  ///< filament bookkeeping: retractions and their primes cancel

    char letter_;
    bool relative_;
    double position_mm_ = 0;       ///< firmware's idea of the position (absolute mode)
    double written_mm_ = 0;        ///< rounded value last written, so rounding never accumulates
    long long written_units_ = 0;  ///< moveUnits(): the rounded position last accounted for
    double total_mm_ = 0;
    double retracted_mm_ = 0;  ///< outstanding retraction, re-primed moves are not new filament
};

}  // namespace mixengine
