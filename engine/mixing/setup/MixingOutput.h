#pragma once
// What the G-code writer needs to know about a mixing nozzle: whether mixing is on, the firmware
// dialect that carries the mix, the number of filament channels, the firmware's mix resolution and
// its tool numbers. Plain data, parsed from the settings by mixing/setup/MixingSettings.h; the default
// value is "no mixing", which writes exactly the single-colour G-code.
#include <string>

namespace mixengine {

enum class MixingMode {
    Single,    ///< one filament: the ordinary E axis, no mixing output at all
    Dual,      ///< a fixed mix per mesh (mixing_ratio)
    Gradient,  ///< the mix follows the height (mixing_gradient_*)
    Color,     ///< a fixed mix per mesh, solved from its mixing_target_color (mixing/color/ColorSolver.h)
};

enum class MixDialectKind {
    EbAxes,      ///< MakerPi style: E and B words on every move, M82/M83 and G92 act on both
    KlipperB,    ///< Klipper manual_stepper on axis B: B absolute (G90), G92 never touches it
    RrfColon,    ///< RepRapFirmware `G1 E<a>:<b>`, relative extrusion only
    MarlinM163,  ///< Marlin M163 S<i> P<f> … M164 S<tool> T<tool>, total E in G1
    MarlinM165,  ///< Marlin M165 A.. B.. (DIRECT_MIXING_IN_G1), total E in G1
    RrfM567,     ///< RepRapFirmware M567 P<tool> E<a>:<b>, total E in G1
};

struct MixingOutput {
    MixingMode mode = MixingMode::Single;
    MixDialectKind dialect = MixDialectKind::EbAxes;
    int channels = 2;
    int resolution_steps = 100;                ///< mix commands carry shares in multiples of 1/steps
    int tool = 0;                              ///< virtual tool (M164 S/T) or RRF tool (M567 P)
    std::string klipper_stepper = "mixing_b";  ///< [manual_stepper NAME] driving axis B

    bool enabled() const { return mode != MixingMode::Single; }
    /// RepRapFirmware accepts `E a:b` only with M83: the whole print is then written relative.
    bool forcesRelativeExtrusion() const { return enabled() && dialect == MixDialectKind::RrfColon; }
};

/// The setting value naming `kind` (e.g. "marlin_m163").
const char* dialectName(MixDialectKind kind);

}  // namespace mixengine
