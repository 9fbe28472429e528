#include "gcode/MotionCommands.h"

#include "gcode/format/NumberFormat.h"

namespace mixengine {

std::vector<std::string> MotionCommands::acceleration(double mm_s2, bool travel) {
    if (mm_s2 <= 0)
        return {};
    const std::string a = formatDecimal(mm_s2, 0);
    if (forms_.travel_acceleration.empty())
        travel = false;  // one acceleration for both
    double& current = travel ? travel_mm_s2_ : print_mm_s2_;
    if (current == mm_s2)
        return {};
    current = mm_s2;
    std::string line(travel ? forms_.travel_acceleration : forms_.print_acceleration);
    line += a;
    if (forms_.acceleration_y)
        line += " Y" + a;
    return {line};
}

std::vector<std::string> MotionCommands::jerk(double mm_s) {
    if (mm_s <= 0 || mm_s == jerk_mm_s_)
        return {};
    jerk_mm_s_ = mm_s;
    const std::string j = formatDecimal(mm_s * forms_.jerk_scale, 2);
    std::string line(forms_.jerk);
    line += j;
    if (forms_.jerk_y)
        line += " Y" + j;
    return {line};
}

}  // namespace mixengine
