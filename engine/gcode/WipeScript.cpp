#include "gcode/WipeScript.h"

namespace mixengine {

void writeWipeScript(const WipeScriptConfig& config, GCodeExport& gcode) {
    const Point2 back = gcode.position();
    gcode.comment("WIPE_SCRIPT_BEGIN");
    if (config.retraction_enable)
        gcode.retractTo(config.retraction);
    if (config.hop_enable && config.hop_um > 0)
        gcode.hopTo(config.hop_um, true, config.hop_speed_mm_s);
    gcode.travel({config.brush_x_um, gcode.position().Y}, config.move_speed_mm_s);
    for (int i = 0; i < config.repeat_count; ++i) {
        const coord_um step = i % 2 == 0 ? config.move_distance_um : -config.move_distance_um;
        gcode.travel({gcode.position().X + step, gcode.position().Y}, config.move_speed_mm_s);
    }
    gcode.travel(back, config.move_speed_mm_s);
    if (config.hop_enable)
        gcode.hopTo(0, false, config.hop_speed_mm_s);
    if (config.retraction_enable)
        gcode.unretract();
    if (config.pause_s > 0)
        gcode.dwell(config.pause_s);
    gcode.comment("WIPE_SCRIPT_END");
}

}  // namespace mixengine
