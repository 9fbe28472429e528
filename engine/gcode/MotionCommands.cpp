#include "gcode/MotionCommands.h"

#include "gcode/NumberFormat.h"

namespace mixengine {

MotionFlavor motionFlavor(const std::string& machine_gcode_flavor) {
    if (machine_gcode_flavor == "RepRap (RepRap)")
        return MotionFlavor::RepRap;
    if (machine_gcode_flavor == "Repetier")
        return MotionFlavor::Repetier;
    return MotionFlavor::Marlin;
}

std::vector<std::string> MotionCommands::acceleration(double mm_s2, bool travel) {
    if (mm_s2 <= 0)
        return {};
    const std::string a = formatDecimal(mm_s2, 0);
    if (flavor_ == MotionFlavor::Marlin)
        travel = false;  // one acceleration for both
    double& current = travel ? travel_mm_s2_ : print_mm_s2_;
    if (current == mm_s2)
        return {};
    current = mm_s2;
    if (flavor_ == MotionFlavor::Repetier)
        return {(travel ? "M202 X" : "M201 X") + a + " Y" + a};
    if (flavor_ == MotionFlavor::RepRap)
        return {(travel ? "M204 T" : "M204 P") + a};
    return {"M204 S" + a};
}

std::vector<std::string> MotionCommands::jerk(double mm_s) {
    if (mm_s <= 0 || mm_s == jerk_mm_s_)
        return {};
    jerk_mm_s_ = mm_s;
    if (flavor_ == MotionFlavor::Repetier)
        return {"M207 X" + formatDecimal(mm_s, 2)};
    if (flavor_ == MotionFlavor::RepRap) {
        const std::string j = formatDecimal(mm_s * 60, 2);
        return {"M566 X" + j + " Y" + j};
    }
    const std::string j = formatDecimal(mm_s, 2);
    return {"M205 X" + j + " Y" + j};
}

}  // namespace mixengine
