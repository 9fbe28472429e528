#include "planning/PreheatModel.h"

#include <algorithm>

namespace mixengine {
namespace {

/// Seconds per degree of heating and of cooling.
struct DegreeSeconds {
    double heat = 0;
    double cool = 0;
};

DegreeSeconds degreeSeconds(const HeaterRates& r, bool printing) {
    const double extra = printing ? r.extrusion_cool_c_per_s : 0.0;
    return {1.0 / (r.heat_up_c_per_s - extra), 1.0 / (r.cool_down_c_per_s + extra)};
}

/// The part of `free_s` (a cool-then-heat or heat-then-cool excursion) spent on its second leg.
double secondLegSeconds(const DegreeSeconds& d, double free_s) {
    return free_s * d.heat / (d.cool + d.heat);
}

}  // namespace

double secondsToReach(const HeaterRates& rates, double from_c, double to_c, bool printing) {
    const double extra = printing ? rates.extrusion_cool_c_per_s : 0.0;
    const double seconds = to_c > from_c ? (to_c - from_c) / (rates.heat_up_c_per_s - extra)
                                         : (from_c - to_c) / (rates.cool_down_c_per_s + extra);
    return std::max(0.0, seconds);
}

WarmUp warmUpAfterCoolDown(const HeaterRates& rates, double window_s, double start_c, double mid_c,
                           double end_c, bool printing) {
    const DegreeSeconds d = degreeSeconds(rates, printing);
    WarmUp out;
    out.window_s = window_s;
    // The direct change between the two ends comes first; what is left of the window is free.
    const bool heats = start_c < end_c;
    out.heating_s = heats ? (end_c - start_c) * d.heat : 0.0;
    const double free_s = window_s - (heats ? out.heating_s : (start_c - end_c) * d.cool);
    const double outer_c = heats ? start_c : end_c;
    if (free_s < 0) {
        out.heating_s = 0;
        out.lowest_c = std::min(start_c, end_c);
        return out;
    }
    const double back_up_s = secondsToReach(rates, mid_c, outer_c, printing);
    if (back_up_s * (1.0 + d.cool / d.heat) < free_s) {  // down to mid_c and back up fit
        out.heating_s += back_up_s;
        out.lowest_c = mid_c;
    } else {
        out.heating_s += secondLegSeconds(d, free_s);
        out.lowest_c = std::max(mid_c, end_c - out.heating_s / d.heat);
    }
    return out;
}

CoolDown coolDownAfterWarmUp(const HeaterRates& rates, double window_s, double start_c, double mid_c,
                             double end_c, bool printing) {
    const DegreeSeconds d = degreeSeconds(rates, printing);
    CoolDown out;
    out.window_s = window_s;
    const bool heats = start_c < end_c;
    out.cooling_s = heats ? 0.0 : (start_c - end_c) * d.cool;
    const double free_s = window_s - (heats ? (end_c - start_c) * d.heat : out.cooling_s);
    const double outer_c = heats ? end_c : start_c;
    if (free_s < 0) {
        out.cooling_s = 0;
        out.highest_c = std::max(start_c, end_c);
        return out;
    }
    const double down_s = secondsToReach(rates, mid_c, outer_c, printing);
    if (down_s * (1.0 + d.cool / d.heat) < free_s) {  // up to mid_c and back down fit
        out.cooling_s += down_s;
        out.highest_c = mid_c;
    } else {
        out.cooling_s += secondLegSeconds(d, free_s);
        out.highest_c = std::min(mid_c, end_c + out.cooling_s / d.cool);
    }
    return out;
}

}  // namespace mixengine
