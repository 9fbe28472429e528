#include "gcode/TemperatureCommands.h"

#include <algorithm>

#include "gcode/format/NumberFormat.h"

namespace mixengine {

TemperatureCommands::Nozzle& TemperatureCommands::nozzle(int extruder) {
    const auto index = static_cast<std::size_t>(extruder < 0 ? 0 : extruder);
    if (nozzles_.size() <= index)
        nozzles_.resize(index + 1);
    return nozzles_[index];
}

bool TemperatureCommands::controlled(int extruder) const {
    const auto index = static_cast<std::size_t>(extruder < 0 ? 0 : extruder);
    return index >= params_.controlled.size() || params_.controlled[index];
}

void TemperatureCommands::assume(int extruder, double celsius, bool waited) {
    nozzle(extruder) = {celsius, waited};
}

void TemperatureCommands::shareHeater(int extruder, double celsius, bool wait) {
    const std::size_t count = std::max(nozzles_.size(), params_.controlled.size());
    for (std::size_t e = 0; e < count; ++e) {
        if (static_cast<int>(e) == extruder)
            continue;
        Nozzle& other = nozzle(static_cast<int>(e));
        if (wait || celsius > other.celsius)
            other.waited = wait;
        other.celsius = celsius;
    }
}

std::vector<std::string> TemperatureCommands::set(int extruder, double celsius, bool wait, int active) {
    if (!controlled(extruder))
        return {};
    if (params_.share_heater) {
        if (extruder != active)
            return {};
        shareHeater(extruder, celsius, wait);
    }
    Nozzle& n = nozzle(extruder);
    if ((!wait || n.waited) && n.celsius == celsius)
        return {};
    std::vector<std::string> lines;
    if (wait && m105_before_wait_)
        lines.emplace_back("M105");
    std::string command = wait ? "M109" : "M104";
    if (extruder != active)
        command += " T" + std::to_string(extruder);
    lines.push_back(command + " S" + formatDecimal(celsius, 1));
    if (extruder != active && params_.always_write_active_tool)
        lines.push_back("T" + std::to_string(active));
    n = {celsius, wait};
    return lines;
}

}  // namespace mixengine
