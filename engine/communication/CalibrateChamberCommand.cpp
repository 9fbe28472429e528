// `mixengine calibrate-chamber`: a print that measures the mixing chamber (issue 26). A thin square tower
// (one wall, spiralize) is generated in memory and sliced through the normal pipeline with the printer's
// settings, as a gradient in mm that switches hard from filament A to B and back at known heights, with
// mixing_chamber_volume forced to 0: the G-code switches at once, so the blur on the printed tower is the
// chamber's own step response. The switch heights and the extrusion per mm of tower height are read from
// the sliced plan; the guide (communication/ChamberCalibration.h) is printed and written as ;CALIBRATION:
// comments after the G-code header.
#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <initializer_list>
#include <optional>
#include <tuple>

#include "common/Error.h"
#include "common/Log.h"
#include "common/ParallelFor.h"
#include "communication/ChamberCalibration.h"
#include "communication/CommandLineParser.h"
#include "communication/Commands.h"
#include "communication/OutputFile.h"
#include "mixing/Preview.h"
#include "mixing/color/ColorSpace.h"
#include "mixing/setup/MixingSettings.h"
#include "pipeline/FffProcessor.h"

namespace mixengine {
namespace {

constexpr double kSideMm = 8;          // the tower's outside: ~12 mm³ per mm of height with a 0.4 mm wall
constexpr double kFirstSwitchMm = 10;  // A up to here: ~150 mm³ flush the start code's purge mix
constexpr double kDefaultBandMm = 15;  // B for this long, then A again for as long
constexpr const char* kTowerName = "chamber_calibration_tower";

struct CalibrateOptions {
    Words slice_args;
    double band_mm = kDefaultBandMm;
    int channel_a = 0;  ///< 0-based
    int channel_b = 1;
};

double parseBand(const std::string& text) {
    std::size_t used = 0;
    double band = 0;
    try {
        band = std::stod(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != text.size() || !(band >= 3 && band <= 100))
        throw InputError("--band: '" + text + "' is not a height in mm from 3 to 100");
    return band;
}

std::pair<int, int> parseFilaments(const std::string& text) {
    const std::size_t comma = text.find(',');
    int a = 0, b = 0;
    try {
        a = comma == std::string::npos ? 0 : std::stoi(text.substr(0, comma));
        b = comma == std::string::npos ? 0 : std::stoi(text.substr(comma + 1));
    } catch (const std::exception&) {
        a = b = 0;
    }
    if (a < 1 || b < 1 || a > kMaxMixChannels || b > kMaxMixChannels || a == b)
        throw InputError("--filaments: '" + text + "' is not two different filament numbers, e.g. 1,2");
    return {a - 1, b - 1};
}

CalibrateOptions parseOptions(const Words& args) {
    CalibrateOptions options;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& word = args[i];
        if (word != "--band" && word != "--filaments") {
            options.slice_args.push_back(word);
            continue;
        }
        if (i + 1 == args.size())
            throw InputError(word + ": a value is needed");
        if (word == "--band")
            options.band_mm = parseBand(args[++i]);
        else
            std::tie(options.channel_a, options.channel_b) = parseFilaments(args[++i]);
    }
    return options;
}

/// A closed box `side` × `side` × `height` mm, centred in XY, bottom at z = 0, outward facets.
TriangleSoup towerSoup(double side, double height) {
    const double h = side / 2;
    const std::array<Vec3, 8> v{{{-h, -h, 0},
                                 {h, -h, 0},
                                 {h, h, 0},
                                 {-h, h, 0},
                                 {-h, -h, height},
                                 {h, -h, height},
                                 {h, h, height},
                                 {-h, h, height}}};
    const int faces[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                              {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
    TriangleSoup soup;
    soup.name = kTowerName;
    for (const auto& face : faces)
        soup.triangles.push_back({v[static_cast<std::size_t>(face[0])], v[static_cast<std::size_t>(face[1])],
                                  v[static_cast<std::size_t>(face[2])]});
    return soup;
}

std::string ratioOf(int channel, int channels) {
    std::string text;
    for (int c = 0; c < channels; ++c)
        text += std::string(c ? ":" : "") + (c == channel ? "1" : "0");
    return text;
}

std::string heightText(double mm) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", mm);
    return buffer;
}

/// "10=1:0; 10=0:1; 25=0:1; 25=1:0": A, a hard switch to B, B, a hard switch back to A.
std::string stopsText(const CalibrateOptions& o, int channels, double first, double second) {
    const std::string a = ratioOf(o.channel_a, channels), b = ratioOf(o.channel_b, channels);
    return heightText(first) + "=" + a + "; " + heightText(first) + "=" + b + "; " + heightText(second) +
           "=" + b + "; " + heightText(second) + "=" + a;
}

/// The tower's shape, unless the user says otherwise (-s after the profile).
void addShapeDefaults(SettingValues& global) {
    for (const auto& [key, value] :
         std::initializer_list<std::pair<const char*, const char*>>{{"magic_spiralize", "True"},
                                                                    {"wall_line_count", "1"},
                                                                    {"infill_sparse_density", "0"},
                                                                    {"top_layers", "0"},
                                                                    {"support_enable", "False"}})
        global.emplace(key, value);
}

/// One mesh extrusion of the sliced tower: where the nozzle ends it, its volume and its share of B.
struct TowerMove {
    double end_mm = 0;
    double volume_mm3 = 0;
    double share_b = 0;
};

struct TowerReading {
    std::vector<TowerMove> moves;
    double all_volume_mm3 = 0;
};

void readPlan(const PrintPlan& plan, int channel_b, TowerReading& reading) {
    for (const PlannedLayer& layer : plan.layers) {
        int mesh = -1;
        for (const PlanStep& step : layer.steps) {
            if (step.kind == PlanStep::Kind::SetMesh)
                mesh = step.mesh_index;
            if (step.kind != PlanStep::Kind::Extrude)
                continue;
            reading.all_volume_mm3 += step.volume_mm3;
            if (mesh < 0 || step.mix < 0)
                continue;
            const double share = plan.mixes[static_cast<std::size_t>(step.mix)][channel_b];
            reading.moves.push_back(
                {static_cast<double>(layer.z + step.rise_um) / 1000.0, step.volume_mm3, share});
        }
    }
}

/// Where the G-code changes between A and B: the end of the last move before each change.
std::vector<double> switchHeights(const TowerReading& reading) {
    std::vector<double> heights;
    for (std::size_t i = 1; i < reading.moves.size(); ++i)
        if ((reading.moves[i].share_b > 0.5) != (reading.moves[i - 1].share_b > 0.5))
            heights.push_back(reading.moves[i - 1].end_mm);
    return heights;
}

/// The extruded volume per mm of height between `lo` and `hi` (moves ending in (lo, hi]).
double volumePerMm(const TowerReading& reading, double lo, double hi) {
    double volume = 0;
    for (const TowerMove& move : reading.moves)
        if (move.end_mm > lo && move.end_mm <= hi)
            volume += move.volume_mm3;
    return volume / (hi - lo);
}

std::string filamentName(const Settings& global, int channel, int channels) {
    const std::vector<Rgb> colors = parseChannelColors(global, channels);
    return "filament " + std::to_string(channel + 1) + " (" +
           hexOf(colors[static_cast<std::size_t>(channel)]) + ")";
}

int channelCount(const Settings& global) {
    return static_cast<int>(global.integer(key::mixing_channels));
}

void checkRequest(const SliceRequest& request, const CalibrateOptions& options, const Settings& global) {
    for (const MeshGroupInput& group : request.groups)
        if (!group.meshes.empty())
            throw InputError("calibrate-chamber: the tower is generated; -l " + group.meshes.front().name +
                             " is not taken");
    if (request.groups.size() > 1)
        throw InputError("calibrate-chamber: --next is not taken (one tower, one mesh group)");
    if (request.output.empty())
        throw InputError("calibrate-chamber: -o <file.gcode> is needed (the guide goes to standard output)");
    if (global.text(key::adhesion_type) == "raft")
        throw InputError(
            "calibrate-chamber: adhesion_type raft lifts the tower off the plate; use skirt, brim or none");
    const int channels = channelCount(global);
    if (std::max(options.channel_a, options.channel_b) >= channels)
        throw InputError("calibrate-chamber: --filaments " + std::to_string(options.channel_a + 1) + "," +
                         std::to_string(options.channel_b + 1) + ": the printer has " +
                         std::to_string(channels) + " filaments (mixing_channels)");
}

/// The request as sliced: the tower as its one model, the shape defaults under the user's values and the
/// calibration's mixing settings over them.
SliceRequest towerRequest(SliceRequest request, const CalibrateOptions& options, int channels,
                          double height) {
    addShapeDefaults(request.user.global);
    const double second = kFirstSwitchMm + options.band_mm;
    for (const auto& [key, value] : std::initializer_list<std::pair<std::string, std::string>>{
             {"mixing_mode", "gradient"},
             {"mixing_gradient_unit", "mm"},
             {"mixing_gradient_stops", stopsText(options, channels, kFirstSwitchMm, second)},
             {"mixing_gradient_colors", ""},
             {"mixing_chamber_volume", "0"}})
        request.user.global[key] = value;
    if (request.groups.empty())
        request.groups.emplace_back();
    MeshInput tower;
    tower.name = kTowerName;
    tower.soups.push_back(towerSoup(kSideMm, height));
    request.groups.front().meshes.push_back(std::move(tower));
    return request;
}

std::string calibrationComments(const std::vector<std::string>& guide) {
    std::string text;
    for (const std::string& line : guide)
        text += ";CALIBRATION: " + line + "\n";
    return text;
}

CalibrationTower describe(const TowerReading& reading, const CalibrateOptions& options, double height) {
    CalibrationTower tower;
    tower.side_mm = kSideMm;
    tower.height_mm = height;
    tower.first_mm = kFirstSwitchMm;
    tower.second_mm = kFirstSwitchMm + options.band_mm;
    const std::vector<double> switches = switchHeights(reading);
    if (switches.size() != 2)
        throw InputError("calibrate-chamber: the sliced tower switches filament " +
                         std::to_string(switches.size()) +
                         " times, not twice (do the settings given leave its walls in place?)");
    tower.switch1_mm = switches[0];
    tower.switch2_mm = switches[1];
    // Away from the bottom layers and the top: half way below the first switch to half way above the second.
    tower.per_mm_mm3 = volumePerMm(reading, tower.switch1_mm / 2, (tower.switch2_mm + height) / 2);
    if (!(tower.per_mm_mm3 > 0))
        throw InputError("calibrate-chamber: the sliced tower extrudes nothing between its switches");
    tower.filament_mm3 = reading.all_volume_mm3;
    return tower;
}

}  // namespace

int runCalibrateChamberCommand(const Words& args, std::ostream& out, std::ostream& err) {
    const CalibrateOptions options = parseOptions(args);
    const ParsedSliceArgs parsed = parseSliceArguments(options.slice_args);
    Log log(err, parsed.request.verbosity);
    log.setProgress(parsed.request.progress);
    // The profile's own chamber (before the calibration sets it to 0), to say what it predicts.
    const Scene profile = prepareSettings(parsed.request);
    checkRequest(parsed.request, options, profile.machine.global);
    const ChamberSpec current = parseChamberSpec(profile.machine.global);
    const int channels = channelCount(profile.machine.global);
    const double height = kFirstSwitchMm + 2 * options.band_mm;

    const Scene scene = prepareScene(towerRequest(parsed.request, options, channels, height), log);
    TowerReading reading;
    std::optional<SidePreview> preview;
    if (!parsed.preview_png.empty())
        preview.emplace(SidePreview::forSettings(scene.machine.global));
    const PlanObserver observe = [&](const PrintPlan& plan) {
        readPlan(plan, options.channel_b, reading);
        if (preview)
            preview->add(plan);
    };
    GCodeOutput gcode = runPipeline(scene, effectiveThreads(parsed.request.threads), log, observe);

    CalibrationTower tower = describe(reading, options, height);
    tower.filament_a = filamentName(scene.machine.global, options.channel_a, channels);
    tower.filament_b = filamentName(scene.machine.global, options.channel_b, channels);
    tower.current = current;
    tower.print_time_s = gcode.summary.print_time_s;
    const std::vector<std::string> guide = calibrationGuide(tower);
    gcode.header += calibrationComments(guide);
    writeFileAtomically(parsed.request.output, gcode.pieces());
    if (preview)
        writeFileAtomically(parsed.preview_png, preview->png());
    out << "G-code written to " << std::filesystem::absolute(parsed.request.output).string() << '\n';
    for (const std::string& line : guide)
        out << line << '\n';
    return 0;
}

}  // namespace mixengine
