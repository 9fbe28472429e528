#pragma once
// The wipe script between layers (clean_between_layers), written as CuraEngine 4.13 writes it:
//   ;WIPE_SCRIPT_BEGIN
//   the wipe retraction (wipe_retraction_enable: to wipe_retraction_amount at
//     wipe_retraction_retract_speed, adding wipe_retraction_extra_prime_amount to the next prime),
//   the lift (wipe_hop_enable: wipe_hop_amount above the layer at wipe_hop_speed),
//   a travel to x = wipe_brush_pos_x at the head's y, then wipe_repeat_count travels of
//     wipe_move_distance, alternately +x and −x, all at speed_travel,
//   the travel back to where the head was, the lowering (at wipe_hop_speed), the prime (at
//     wipe_retraction_prime_speed), a pause of wipe_pause seconds (G4) when above 0,
//   ;WIPE_SCRIPT_END
// On a mixing printer the retraction and prime move every mixing axis, as other retractions do.
#include "gcode/GCodeExport.h"

namespace mixengine {

struct WipeScriptConfig {
    bool retraction_enable = true;
    RetractionConfig retraction;
    double pause_s = 0;
    bool hop_enable = false;
    coord_um hop_um = 1000;
    double hop_speed_mm_s = 10;
    coord_um brush_x_um = 100'000;
    int repeat_count = 5;
    coord_um move_distance_um = 20'000;
    double move_speed_mm_s = 150;  ///< speed_travel
};

void writeWipeScript(const WipeScriptConfig& config, GCodeExport& gcode);

}  // namespace mixengine
