#pragma once
// One extrusion axis (E, or a second mixing axis) and how the firmware reads its words.
//
// Absolute mode (M82): words carry the running position; the writer resets it with `G92 E0` at
// layer changes (resetNeeded()), so a position never exceeds one layer's filament plus one
// retraction — small enough that a 32-bit float in the firmware keeps 1e-4 mm resolution (seed 004).
// Relative mode (M83): words carry the per-move delta. Both give the same total filament.
//
// Amounts are in the axis unit: mm of filament, or mm³ of material when the flavor is volumetric
// (RepRap (Volumetric), UltiGCode). Words are written with 5 decimals; a "unit" is that resolution,
// 1e-5 of the axis unit.
// moveUnits() is the integer view used by the mixing dialects (gcode/mixdialect/MixDialect.h): how far the
// written value moves, which is exactly what a firmware sees between two words.
#include <string>

namespace mixengine {

inline constexpr double kUnitsPerAxisUnit = 1e5;  ///< written resolution of extrusion words

/// "12.34567" for 1234567 units (no letter).
std::string formatUnits(long long units);

class ExtrusionAxis {
  public:
    ExtrusionAxis(char letter, bool relative) : letter_(letter), relative_(relative) {}

    char letter() const { return letter_; }
    void setLetter(char letter) { letter_ = letter; }  ///< MACH3: A, B, ... per extruder
    bool relative() const { return relative_; }

    /// Moves the axis by `delta` (axis unit) and returns the word to write, e.g. "E12.34567".
    std::string move(double delta);
    /// Moves the axis by `delta` like move() but returns, instead of a word, how many units
    /// the written value moves (absolute: new written position − old; relative: the delta word).
    long long moveUnits(double delta);
    /// Absolute mode: sets the position to 0 and returns "G92 E0"; relative mode: returns "".
    std::string reset();
    /// True when an absolute position is non-zero (a reset is worthwhile).
    bool resetNeeded() const { return !relative_ && position_ != 0.0; }

    double position() const { return position_; }    ///< axis unit
    double totalExtruded() const { return total_; }  ///< axis unit; forward motion only, retractions excluded

  private:
    void account(double delta);  ///< filament bookkeeping: retractions and their primes cancel

    // Amounts in the axis unit.
    char letter_;
    bool relative_;
    double position_ = 0;          ///< firmware's idea of the position (absolute mode)
    double written_ = 0;           ///< rounded value last written, so rounding never accumulates
    long long written_units_ = 0;  ///< moveUnits(): the rounded position last accounted for
    double total_ = 0;
    double retracted_ = 0;  ///< outstanding retraction, re-primed moves are not new filament
};

}  // namespace mixengine
