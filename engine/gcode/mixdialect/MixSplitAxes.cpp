#include "gcode/mixdialect/MixSplitAxes.h"

namespace mixengine {

MixSplitAxes::MixSplitAxes(const MixingOutput& mixing, bool relative_extrusion)
    : mixing_(mixing),
      relative_extrusion_(relative_extrusion),
      total_('E', relative_extrusion),
      last_mix_(MixVector::only(0, mixing.channels)) {
    for (int c = 0; c < mixing.channels; ++c) {
        bool relative = relative_extrusion;
        if (mixing.dialect == MixDialectKind::RrfColon)
            relative = true;
        if (mixing.dialect == MixDialectKind::KlipperB && c == 1)
            relative = false;  // G90: absolute, whatever M82/M83 say
        relative_[static_cast<std::size_t>(c)] = relative;
    }
}

void MixSplitAxes::start(std::string& before) {
    if (started_)
        return;
    started_ = true;
    if (mixing_.dialect == MixDialectKind::KlipperB) {
        const std::string stepper = "MANUAL_STEPPER STEPPER=" + mixing_.klipper_stepper;
        before += ";MIXING: filament B on Klipper manual_stepper '" + mixing_.klipper_stepper +
                  "' as axis B: absolute positions (G90) from 0, never reset by G92\n";
        before +=
            stepper + " GCODE_AXIS=\n" + stepper + " SET_POSITION=0\n" + stepper + " GCODE_AXIS=B\nG90\n";
    } else if (mixing_.dialect == MixDialectKind::EbAxes && !relative_extrusion_) {
        // The print's own "G92 E0" leaves B wherever an earlier job left it: start it from 0 as well.
        before += "G92 B0 ;MIXING: filament A on E, B on B (M82/M83 and G92 act on both)\n";
    } else if (mixing_.dialect == MixDialectKind::RrfColon) {
        before +=
            relative_extrusion_
                ? ";MIXING: E a:b words; RepRapFirmware accepts them only in relative extrusion mode (M83)\n"
                : "M83 ;relative extrusion mode (forced: RepRapFirmware accepts E a:b only with M83)\n";
    }
}

std::string MixSplitAxes::words(const ChannelUnits& moved) {
    static constexpr char kLetters[] = {'E', 'B'};
    std::string text;
    for (int c = 0; c < mixing_.channels; ++c) {
        const auto i = static_cast<std::size_t>(c);
        position_[i] += moved[i];
        const std::string value = formatUnits(relative_[i] ? moved[i] : position_[i]);
        if (mixing_.dialect == MixDialectKind::RrfColon)
            text += (c ? ":" : "E") + value;
        else
            text += (c ? " " : "") + std::string(1, kLetters[c < 2 ? c : 1]) + value;
    }
    return text;
}

std::string MixSplitAxes::extrude(double amount, const MixVector& mix, std::string& before) {
    start(before);
    last_mix_ = mix;
    const ChannelUnits moved = split_.split(total_.moveUnits(amount), mix);
    for (std::size_t i = 0; i < moved.size(); ++i)
        forward_[i] += moved[i];
    return words(moved);
}

std::string MixSplitAxes::retract(double amount, std::string& before) {
    start(before);
    const ChannelUnits moved = split_.split(total_.moveUnits(-amount), last_mix_, false);
    for (std::size_t i = 0; i < moved.size(); ++i)
        retracted_[i] -= moved[i];
    return words(moved);
}

std::string MixSplitAxes::prime(double amount, std::string& before) {
    start(before);
    const long long units = total_.moveUnits(amount);
    ChannelUnits moved = retracted_;
    long long owed = 0;
    for (long long r : retracted_)
        owed += r;
    if (owed == 0) {
        moved = split_.split(units, last_mix_, false);
    } else {
        // The total's rounding may differ by a unit from the retraction: settle it on the channel
        // that gave the most.
        std::size_t most = 0;
        for (std::size_t i = 1; i < moved.size(); ++i)
            most = moved[i] > moved[most] ? i : most;
        moved[most] += units - owed;
    }
    retracted_ = {};
    return words(moved);
}

std::string MixSplitAxes::reset() {
    total_.reset();  // the single-colour track resets where single-colour output would
    std::string line;
    for (int c = 0; c < mixing_.channels; ++c) {
        const auto i = static_cast<std::size_t>(c);
        if (relative_[i])
            continue;
        if (mixing_.dialect == MixDialectKind::KlipperB && c == 1)
            continue;  // G92 cannot touch a manual_stepper axis
        position_[i] = 0;
        line += std::string(" ") + (c == 0 ? 'E' : 'B') + "0";
    }
    return line.empty() ? "" : "G92" + line;
}

std::vector<double> MixSplitAxes::channelTotals() const {
    std::vector<double> totals;
    for (int c = 0; c < mixing_.channels; ++c)
        totals.push_back(static_cast<double>(forward_[static_cast<std::size_t>(c)]) / kUnitsPerAxisUnit);
    return totals;
}

}  // namespace mixengine
