#pragma once
// The nozzle temperature commands, as CuraEngine 4.13's writeTemperatureCommand writes them:
//   M104 [T<n>] S<c> (set), M109 [T<n>] S<c> (set and wait; Marlin: M105 before it, see
//   FlavorTraits::m105_before_wait in gcode/Flavor.h), T<n> only
//   for a nozzle other than the active one, S with up to one decimal;
//   - nothing when the nozzle is already at that temperature (and, for M109, was waited for);
//   - machine_nozzle_temp_enabled = false for the nozzle: nothing;
//   - machine_extruders_share_heater: commands for a nozzle other than the active one are dropped,
//     and one for the active one sets every nozzle (they share the heater);
//   - machine_always_write_active_tool: T<active> after a command naming another nozzle (firmware
//     such as Smoothieware switches tools on any T word).
// The state starts with what the start code set (assume()).
#include <string>
#include <utility>
#include <vector>

namespace mixengine {

struct TemperatureCommandParams {
    bool share_heater = false;              ///< machine_extruders_share_heater
    bool always_write_active_tool = false;  ///< machine_always_write_active_tool
    std::vector<bool> controlled;           ///< machine_nozzle_temp_enabled by extruder_nr (absent: true)
};

class TemperatureCommands {
  public:
    /// `m105_before_wait`: M105 before every M109 (the flavor's, gcode/Flavor.h).
    explicit TemperatureCommands(TemperatureCommandParams params = {}, bool m105_before_wait = false)
        : params_(std::move(params)), m105_before_wait_(m105_before_wait) {}

    /// What the start code left: nozzle `extruder` at `celsius`, waited for or not.
    void assume(int extruder, double celsius, bool waited);
    /// The lines setting nozzle `extruder` to `celsius` (`wait`: M109) while `active` is the active tool.
    std::vector<std::string> set(int extruder, double celsius, bool wait, int active);

  private:
    struct Nozzle {
        double celsius = 0;
        bool waited = false;
    };
    Nozzle& nozzle(int extruder);
    bool controlled(int extruder) const;
    void shareHeater(int extruder, double celsius, bool wait);

    TemperatureCommandParams params_;
    bool m105_before_wait_;
    std::vector<Nozzle> nozzles_;
};

}  // namespace mixengine
