#pragma once
// CuraEngine 4.13's model of a nozzle heater (its Preheat): the nozzle heats at
// machine_nozzle_heat_up_speed and cools at machine_nozzle_cool_down_speed (°C/s); while it prints,
// the flowing material cools it by material_extrusion_cool_down_speed more (heating is that much
// slower, cooling that much faster). Temperatures change linearly at those rates.
//
// Two questions of the model place the temperature commands around extruder switches
// (planning/SwitchTemperatures.h):
//   - warm-up after cool-down: a nozzle at `start_c` is left for `window_s` and must be at `end_c`
//     when it is used again; it cools towards the standby temperature `mid_c` first, then heats.
//     Returns when the heating must begin (heating_s before the end of the window) and the lowest
//     temperature reached (mid_c, or higher when the window is too short to get there and back);
//   - cool-down after warm-up: a nozzle printing from `start_c` must end at `end_c` after
//     `window_s`, printing at `mid_c` in between. Returns when the cooling must begin (cooling_s
//     before the end) and the highest temperature reached.
// A window too short even for the direct change gives 0 s and the nearer end temperature.

namespace mixengine {

struct HeaterRates {
    double heat_up_c_per_s = 2;           ///< machine_nozzle_heat_up_speed
    double cool_down_c_per_s = 2;         ///< machine_nozzle_cool_down_speed
    double extrusion_cool_c_per_s = 0.7;  ///< material_extrusion_cool_down_speed
};

/// Seconds from `from_c` to `to_c` (0 when not slower than 0), `printing` or idle.
double secondsToReach(const HeaterRates& rates, double from_c, double to_c, bool printing);

struct WarmUp {
    double window_s = 0;
    double heating_s = 0;  ///< heating starts this long before the window ends
    double lowest_c = 0;
};

WarmUp warmUpAfterCoolDown(const HeaterRates& rates, double window_s, double start_c, double mid_c,
                           double end_c, bool printing);

struct CoolDown {
    double window_s = 0;
    double cooling_s = 0;  ///< cooling starts this long before the window ends
    double highest_c = 0;
};

CoolDown coolDownAfterWarmUp(const HeaterRates& rates, double window_s, double start_c, double mid_c,
                             double end_c, bool printing);

}  // namespace mixengine
