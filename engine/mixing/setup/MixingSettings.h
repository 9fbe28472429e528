#pragma once
// Parsing and validation of the `mixing` settings (settings/mixengine/mixing.def.json). Every
// key has a default in code, so the engine behaves (single mode) when the definition file is
// absent. Values are checked only when mixing is on (mixing_mode dual, gradient or color); a bad value
// is an InputError of one line naming the setting, thrown before any G-code is written.
//
// Formats:
//   mixing_ratio            "0.3:0.7" — one share per channel (fractions, colon-separated,
//                           missing channels are 0); they must add up to 1.
//   mixing_raft_ratio       the same form, for the raft (adhesion_type raft); default "1":
//                           filament A only.
//   mixing_support_ratio    the same form, for the support (normal and tree, body and
//                           interface) and the draft shield; default "1": filament A only.
//   mixing_gradient_stops   "0=1:0; 50=0:1; 100=0.5:0.5" — height (in mixing_gradient_unit)
//                           = ratios; heights must not decrease. Empty: the seed's two-stop
//                           gradient from mixing_gradient_start (A only) to mixing_gradient_end
//                           (B only).
//   mixing_channel_colors   "#f2c500,#e0408a,…" — one sRGB colour per channel: the preview, and
//                           the filament colours that colour mode and gradient colours mix.
//   mixing_target_color     "#ff8000" — color mode: the colour a mesh is printed in (solved to a
//                           mix by mixing/color/ColorSolver.h).
//   mixing_gradient_colors  "0=#ff0000; 100=#0000ff" — gradient mode: stops given as colours
//                           (height=#rrggbb; heights as mixing_gradient_stops), each solved to a
//                           mix; between stops the mixes are interpolated (in the mixing model,
//                           not in RGB). Takes precedence over mixing_gradient_stops when set.
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "mixing/chamber/ChamberModel.h"
#include "mixing/color/ColorSolver.h"
#include "mixing/setup/MixingOutput.h"
#include "planning/MixVector.h"
#include "settings/Settings.h"

namespace mixengine {

enum class HeightUnit {
    Percent,      ///< percent of the mesh's own height (bottom = 0, top = 100)
    Millimetres,  ///< mm above the mesh's bottom
};

/// mixing_gradient_axis: the direction a gradient's stops are measured along.
enum class GradientAxis {
    Z,       ///< height (the seed's gradient)
    X,       ///< from the model's left side
    Y,       ///< from the model's front side
    Radial,  ///< from the model's vertical centre axis outward
};

struct GradientStop {
    double height = 0;  ///< in the schedule's unit
    MixVector mix;
};

/// A colour asked for (mixing_target_color or a gradient colour stop) and the mix solved for it.
struct SolvedColor {
    Rgb target{};
    ColorSolution solution;
};

/// How the extrusions of one mesh (or the non-mesh extrusions, from the group's view) are mixed.
struct MeshMixing {
    MixingMode mode = MixingMode::Single;
    HeightUnit unit = HeightUnit::Percent;
    GradientAxis axis = GradientAxis::Z;
    std::vector<GradientStop> stops;  ///< gradient mode: at least one, heights non-decreasing
    MixVector fixed;                  ///< dual and color mode
    std::vector<SolvedColor> colors;  ///< color mode: the target; gradient colours: one per stop
    /// mixing_core_ratio: the mix its hidden extrusions (infill, inner walls, hidden skin) ask for; empty:
    /// off
    std::optional<MixVector> core;
};

/// The printer-level part (mode, dialect, channels, resolution, tool). Checks the channel count
/// against machine_extruder_count when the printer declares more than one extruder train.
MixingOutput parseMixingOutput(const Settings& global);

/// relative_extrusion, or true when the mixing dialect only works with relative extrusion (M83).
bool relativeExtrusion(const Settings& global);

/// "0.2500:0.7500": a mix's channel shares with four decimals, as the mix command and the logs show it.
std::string ratioText(const MixVector& mix);

/// One scope's schedule (mesh view, or the group's view for non-mesh extrusions). With mixing on
/// (the print's mixing_mode), a scope's own mixing_mode picks its kind of schedule: a model (a
/// cutting mesh's region, an infill mesh) may be dual while the print is a gradient, or the reverse;
/// `single` there means the first filament alone. `colors` solves target colours (color mode,
/// mixing_gradient_colors); without it they are an error.
MeshMixing parseMeshMixing(const Settings& scope, const MixingOutput& output,
                           const PigmentModel* colors = nullptr);

/// mixing_target_color of `scope`, solved with `colors`.
SolvedColor parseTargetColor(const Settings& scope, const PigmentModel& colors);

/// mixing_gradient_colors "h=#rrggbb; …" → stops with solved mixes (empty text: no stops).
std::vector<GradientStop> parseGradientColors(std::string_view text, const PigmentModel& colors,
                                              std::vector<SolvedColor>& solved);

/// mixing_raft_ratio: the mix the raft is printed with (mixing on).
MixVector parseRaftMix(const Settings& global, const MixingOutput& output);

/// mixing_support_ratio: the mix the support and the draft shield are printed with (mixing on).
MixVector parseSupportMix(const Settings& global, const MixingOutput& output);

/// mixing_chamber_volume in mm³ (0 = no delay compensation); negative values are an error.
double parseChamberVolumeMm3(const Settings& global);

/// mixing_chamber_volume and mixing_chamber_stages (1..200).
ChamberSpec parseChamberSpec(const Settings& global);

/// mixing_transition_tolerance, a share in (0, 1].
double parseTransitionTolerance(const Settings& global);

/// mixing_purge_tower_enable.
bool parsePurgeTower(const Settings& global);

/// mixing_channel_colors: `channels` colours (defaults fill missing entries).
std::vector<Rgb> parseChannelColors(const Settings& global, int channels);

/// "0.3:0.7" → a mix of `channels` channels; `key` names the setting in errors.
MixVector parseMixRatio(std::string_view key, std::string_view text, int channels);

/// "h=a:b; h=a:b" → stops; `key` names the setting in errors.
std::vector<GradientStop> parseGradientStops(std::string_view key, std::string_view text, int channels);

}  // namespace mixengine
