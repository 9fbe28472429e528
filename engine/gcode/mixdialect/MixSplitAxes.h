#pragma once
// Dialects that write one amount per filament channel on every extruding move
// (gcode/mixdialect/MixDialect.h):
//
//   eb_axes    "E<a> B<b>"; M82/M83 switch both axes (MakerPi); absolute positions are reset
//              together with "G92 E0 B0" at layer starts (and B once with "G92 B0" before its first
//              word, since the print's start only resets E).
//   klipper_b  "E<a> B<b>"; B is a Klipper manual_stepper registered as a G-code axis, which
//              follows G90/G91 (not M82/M83) and which G92 cannot reset. B is therefore always
//              written as an absolute, ever-growing position (G90), starting from 0: before the
//              first B word the stepper is unregistered, set to 0 and registered again
//              (MANUAL_STEPPER … GCODE_AXIS= / SET_POSITION=0 / GCODE_AXIS=B). Klipper keeps
//              positions in double precision, so the growing B loses nothing (seed 004's float
//              concern is about 32-bit firmware). E follows M82/M83 and G92 E0 as usual.
//   rrf_colon  "E<a>:<b>[:<c>…]"; RepRapFirmware accepts several E values only in relative mode,
//              so the words are always relative, and when the print is set to absolute extrusion
//              an "M83" with a comment is written before the first one.
//
// The move's total follows the single-colour E axis exactly (same positions, same resets), and
// is split into channels by MixChannelSplit, so the channel values of a move add up to the
// single-colour E word. A retraction takes each channel's share of the last mix; the prime puts
// back exactly what each channel gave.
#include <array>

#include "gcode/format/ExtrusionAxis.h"
#include "gcode/mixdialect/MixChannelSplit.h"
#include "gcode/mixdialect/MixDialect.h"

namespace mixengine {

class MixSplitAxes : public MixDialect {
  public:
    MixSplitAxes(const MixingOutput& mixing, bool relative_extrusion);

    std::string extrude(double amount, const MixVector& mix, std::string& before) override;
    std::string retract(double amount, std::string& before) override;
    std::string prime(double amount, std::string& before) override;
    std::string reset() override;
    double totalExtruded() const override { return total_.totalExtruded(); }
    std::vector<double> channelTotals() const override;

  private:
    void start(std::string& before);  ///< once: the dialect's preamble lines
    std::string words(const ChannelUnits& moved);

    MixingOutput mixing_;
    bool relative_extrusion_;
    ExtrusionAxis total_;  ///< the single-colour E axis: decides each move's units
    MixChannelSplit split_;
    std::array<bool, kMaxMixChannels> relative_{};       ///< per channel: words are deltas
    std::array<long long, kMaxMixChannels> position_{};  ///< per channel, absolute channels (units)
    std::array<long long, kMaxMixChannels> forward_{};   ///< per channel, extrusion only (units)
    ChannelUnits retracted_{};                           ///< taken by the outstanding retraction
    MixVector last_mix_;
    bool started_ = false;
};

}  // namespace mixengine
