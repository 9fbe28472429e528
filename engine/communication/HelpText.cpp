#include "communication/HelpText.h"

#include <array>
#include <utility>

namespace mixengine {
namespace {

constexpr std::string_view kIntro =
    "MixEngine — a CuraEngine 4.13 compatible slicer for mixing-chamber and dual-nozzle "
    "printers.\n\nusage:\n";

constexpr std::string_view kHelp = R"(mixengine help [<command>]
	Show this help message, or the usage of one command (as `mixengine <command> --help`).
)";

constexpr std::string_view kSlice =
    R"(mixengine slice [-v] [-p] [-m<threads>] [-j <definition.def.json>] [-s <key>=<value>] [-g] [-e<N>] [-l <model>] [--next] [-o <output.gcode>]
  -v            Increase the verbose level (log messages to stderr; -vv for debug).
  -p            Log progress information.
  -m<threads>   Number of threads (default: all cores).
  -j <file|id>  Machine definition with its inherits chain and extruder trains. Searched in
                CURA_ENGINE_SEARCH_PATH (':' or ';' separated), then Cura's installed resources.
                Default: fdmprinter.def.json from the installed Cura.
  -s key=value  Set a setting for the current focus: global settings, the mesh group (-g),
                the extruder train (-e<N>), or the last model (-l). Unknown keys are kept.
  -g            Focus on the current mesh group (one-at-a-time printing).
  -e<N>         Focus on extruder train N; models loaded next print with it.
  -l <model>    Load a model (STL binary/ASCII, OBJ, 3MF). mesh_rotation_matrix set before -l
                applies to it (it may also scale).
  --next        Start a new mesh group, printed after the previous one.
  -o <file>     Write the G-code to <file> (written to a temporary file, renamed when complete).
                Without -o the G-code goes to standard output.
  --dump-layers <dir>  Also write every layer's outlines as JSON and SVG into <dir>.
  --preview <file.png>  Also write a side view of the print coloured by the filament mix (colour mixing:
                -s mixing_mode=gradient|dual|color, mixing_* settings; seed aliases colorMode, colorA, colorB;
                color mode and mixing_gradient_colors draw the colours the pigment model predicts).
  --profiles    Stack Cura's profiles under the user's values, as Cura does: the machine's default
                variant (nozzle), material, quality and intent. Implied by any of:
  --variant <name>  --material <name>  --quality <name>  --intent <name>
                Choose a profile by name or id, e.g. --quality normal --material generic_pla;
                --variant and --material take one name per extruder, comma-separated
                ("AA 0.4,BB 0.4"); an unknown name lists the available ones.
                Without these the definitions alone apply (as CuraEngine's command line does),
                but their `value` formulas are always evaluated, so derived settings follow.
                With them, values resolve as in Cura's stacks, and a -s value wins over every
                profile (as a value set in Cura does); -e<N> -s sets one extruder's alone.
  --help, -h    Show this usage.

	Settings are appended to the last supplied object:
	mixengine slice [general settings]
		-g [current group settings]
		-e0 [extruder train 0 settings]
		-l obj_inheriting_from_last_extruder_train.stl [object settings]
		--next [next group settings]
		... etc.
)";

constexpr std::string_view kConnect = R"(mixengine connect <host>[:<port>] [-v] [-m<threads>]
	Cura's engine mode: connect to Cura's socket (Arcus protocol, port 49674 by default), wait
	for one Slice message, slice it with the settings Cura sends, stream back the G-code layer by
	layer, the layer preview, the header and the print time / material estimates, then exit 0.
	Cura starts it as `mixengine connect 127.0.0.1:<port> ""`; other flags are ignored with a
	warning, as CuraEngine does. SIGTERM (Cura cancelling a slice) ends it at once.
)";

constexpr std::string_view kLayers = R"(mixengine layers <slice arguments> -o <dir>
	Slice only, and write <dir>/layers.json (outlines in mm, area per layer) and one SVG per
	layer (<dir>/layer_00000.svg ...), in the model's own frame, to look at the slices.
	A mixing print (mixing_mode not single) is planned as `slice` plans it, and each SVG also
	draws the layer's extrusions over the outline, as lines of their width in the colour
	predicted to leave the nozzle (the G-code's ;PREDICTED_COLOR:); layers.json adds per layer
	"gcode_layer" (its ;LAYER: number) and "predicted_colors" ([{"color", "length_mm"}]), and
	"raft_layers" for the raft's layers (no SVG). Only the first mesh group is drawn.
	Takes the options of `mixengine slice` (-j, -s, -e<N>, -l, --profiles, ...).
)";

constexpr std::string_view kSettings =
    R"(mixengine settings [-j <definition>] [--profiles ...] [-s key=value] [-e<N>] [--json]
	Print the resolved global and per-extruder setting values (--json: as one JSON document).
)";

constexpr std::string_view kDemo = R"(mixengine demo [<dir>]
	Generate a 20 mm cube in <dir> (default: out), slice it with a colour gradient (filament A up
	to 20 % of the height, B from 80 %), print where the G-code and its preview picture went.
)";

constexpr std::string_view kOrient =
    R"(mixengine orient <partA> <partB> [--offset X,Y] [-j <definition>] [-s key=value] [--method sphere|grid]
                 [--measure own_part|all_material] [--objective flat_face|low_height|low_overhang]
                 [--resolution N] [--verify N] [--grid-step DEG] [-m<threads>]
                 [--report out.json] [--plot out.png] [--write DIR]
	Dual-nozzle orientation (seed 000): the rotation of the two parts (A printed by extruder 0,
	B by extruder 1) that minimises V = vol(A ∩ (A+d)) + vol(B ∩ (B−d)), d = nozzle 1 − nozzle 0
	(--offset, or machine_nozzle_offset_x/y of -j's extruder trains). Prints latitude, longitude,
	spin about d, the matrix, V before/after (exact, CGAL) and the time. One part: nothing to
	optimise (exit 0). In `slice`, -s dual_orientation_optimize=true runs the same pass.
)";

constexpr std::string_view kMix =
    R"(mixengine mix --colors "#rrggbb,#rrggbb[,...]" (--target "#rrggbb" | --ratio a:b[:...])
	Colour mixing without slicing: the filament colours (2 to 5, white and black included) are
	mixed in a pigment model (Kubelka-Munk over reflectance spectra). --target prints the ratios
	that print the colour nearest to the target, the predicted colour and its CIEDE2000 difference
	dE00 (above 2: outside the mixable gamut, the nearest mixable colour); --ratio prints the colour
	a mix is predicted to print. In `slice`: -s mixing_mode=color -s mixing_target_color=#rrggbb.
)";

constexpr std::string_view kCalibrateChamber =
    R"(mixengine calibrate-chamber [-j <definition>] [--profiles ...] [-s key=value] [-e<N>] -o <tower.gcode>
                            [--filaments a,b] [--band <mm>] [--preview <file.png>]
	A print that measures the mixing chamber: an 8 mm square tower, one wall (spiralize), filament a
	(default 1) up to 10 mm, b (default 2) for --band mm (default 15), a again for as long, sliced with the
	printer's settings and mixing_chamber_volume 0, so the G-code switches at once and the blur on the
	tower is the chamber's own. Prints (and writes as ;CALIBRATION: lines after the G-code header) the
	switch heights, the extrusion per mm of tower height and, from the chamber model, the heights above
	a switch where the colour is 10, 50 and 90 % of the way to the new filament for chambers of 10 to
	120 mm3 in 1 to 10 stages: measure the tower, pick the nearest row, set mixing_chamber_volume and
	mixing_chamber_stages. No -l: the tower is the model.
)";

constexpr std::string_view kExitCodes =
    "Exit codes: 0 success, 1 bad input (one line on stderr names the file, key or value), 2 internal "
    "error.\n";

constexpr std::array<std::pair<std::string_view, std::string_view>, 9> kCommands{
    {{"help", kHelp},
     {"slice", kSlice},
     {"connect", kConnect},
     {"layers", kLayers},
     {"settings", kSettings},
     {"demo", kDemo},
     {"orient", kOrient},
     {"mix", kMix},
     {"calibrate-chamber", kCalibrateChamber}}};

}  // namespace

std::string helpText() {
    std::string text(kIntro);
    for (const auto& [name, usage] : kCommands) {
        text += usage;
        text += '\n';
    }
    text += kExitCodes;
    return text;
}

std::optional<std::string> commandHelp(std::string_view command) {
    for (const auto& [name, usage] : kCommands) {
        if (name == command)
            return "usage:\n" + std::string(usage) + '\n' + std::string(kExitCodes);
    }
    return std::nullopt;
}

}  // namespace mixengine
