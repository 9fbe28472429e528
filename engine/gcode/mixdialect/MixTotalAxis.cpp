#include "gcode/mixdialect/MixTotalAxis.h"

#include "gcode/format/NumberFormat.h"
#include "mixing/setup/Quantiser.h"

namespace mixengine {
namespace {

/// M165 / G1 mixing letters of Marlin for mixing steppers 1..6.
constexpr char kM165Letters[] = {'A', 'B', 'C', 'D', 'H', 'I'};

}  // namespace

MixTotalAxis::MixTotalAxis(const MixingOutput& mixing, bool relative_extrusion)
    : mixing_(mixing), axis_('E', relative_extrusion) {}

std::string MixTotalAxis::mixCommand(const std::array<int, kMaxMixChannels>& steps) {
    auto factor = [&](int c) {
        return formatDecimal(
            static_cast<double>(steps[static_cast<std::size_t>(c)]) / mixing_.resolution_steps, 6);
    };
    std::string text;
    switch (mixing_.dialect) {
        case MixDialectKind::MarlinM163:
            for (int c = 0; c < mixing_.channels; ++c)
                text += "M163 S" + std::to_string(c) + " P" + factor(c) + "\n";
            text += "M164 S" + std::to_string(mixing_.tool) + "\n";
            if (!written_)  // the stored mix takes effect once its virtual tool is selected
                text += "T" + std::to_string(mixing_.tool) + "\n";
            break;
        case MixDialectKind::MarlinM165:
            text = "M165";
            for (int c = 0; c < mixing_.channels; ++c)
                text += std::string(" ") + kM165Letters[c] + factor(c);
            text += "\n";
            break;
        case MixDialectKind::RrfM567:
            text = "M567 P" + std::to_string(mixing_.tool) + " E";
            for (int c = 0; c < mixing_.channels; ++c)
                text += (c ? ":" : "") + factor(c);
            text += "\n";
            break;
        default:
            break;
    }
    return text;
}

std::string MixTotalAxis::extrude(double amount, const MixVector& mix, std::string& before) {
    if (mixing_.enabled()) {
        const auto steps = quantiseSteps(mix, mixing_.resolution_steps);
        if (!written_ || *written_ != steps) {
            before += mixCommand(steps);
            written_ = steps;
        }
        for (int c = 0; c < mixing_.channels; ++c)
            channel_totals_[static_cast<std::size_t>(c)] +=
                amount * steps[static_cast<std::size_t>(c)] / mixing_.resolution_steps;
    } else {
        channel_totals_[0] += amount;
    }
    return axis_.move(amount);
}

std::string MixTotalAxis::retract(double amount, std::string&) {
    return axis_.move(-amount);
}

std::string MixTotalAxis::prime(double amount, std::string&) {
    return axis_.move(amount);
}

std::vector<double> MixTotalAxis::channelTotals() const {
    const int channels = mixing_.enabled() ? mixing_.channels : 1;
    return {channel_totals_.begin(), channel_totals_.begin() + channels};
}

}  // namespace mixengine
