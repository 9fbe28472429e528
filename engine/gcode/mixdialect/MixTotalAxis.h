#pragma once
// Dialects with one total E axis (gcode/mixdialect/MixDialect.h): the single-colour output, and the mixing
// firmwares that take the mix as a command — Marlin M163/M164 (+ T<tool> once), Marlin M165
// (DIRECT_MIXING_IN_G1) and RepRapFirmware M567. The E words are exactly the single-colour ones;
// a mix command is written before a move only when the mix, quantised to the firmware's
// resolution (mixing/setup/Quantiser.h), differs from the one last written.
#include <array>
#include <optional>

#include "gcode/format/ExtrusionAxis.h"
#include "gcode/mixdialect/MixDialect.h"

namespace mixengine {

class MixTotalAxis : public MixDialect {
  public:
    /// `mixing.enabled()` false: no mix commands at all (single mode).
    MixTotalAxis(const MixingOutput& mixing, bool relative_extrusion);

    std::string extrude(double amount, const MixVector& mix, std::string& before) override;
    std::string retract(double amount, std::string& before) override;
    std::string prime(double amount, std::string& before) override;
    std::string reset() override { return axis_.reset(); }
    void setAxisLetter(char letter) override { axis_.setLetter(letter); }
    double totalExtruded() const override { return axis_.totalExtruded(); }
    std::vector<double> channelTotals() const override;

  private:
    std::string mixCommand(const std::array<int, kMaxMixChannels>& steps);

    MixingOutput mixing_;
    ExtrusionAxis axis_;
    std::optional<std::array<int, kMaxMixChannels>> written_;  ///< quantised mix last commanded
    std::array<double, kMaxMixChannels> channel_totals_{};
};

}  // namespace mixengine
