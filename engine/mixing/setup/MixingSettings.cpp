#include "mixing/setup/MixingSettings.h"

#include <cstdio>

#include <cmath>
#include <string>

#include "common/Error.h"
#include "settings/ValueParse.h"

namespace mixengine {
namespace {

constexpr double kSumTolerance = 1e-6;

struct DialectEntry {
    MixDialectKind kind;
    const char* name;
};
constexpr DialectEntry kDialects[] = {
    {MixDialectKind::EbAxes, "eb_axes"},         {MixDialectKind::KlipperB, "klipper_b"},
    {MixDialectKind::RrfColon, "rrf_colon"},     {MixDialectKind::MarlinM163, "marlin_m163"},
    {MixDialectKind::MarlinM165, "marlin_m165"}, {MixDialectKind::RrfM567, "rrf_m567"},
};

/// The colours of the channels mixing_channel_colors leaves out (a list shorter than the channels).
constexpr std::string_view kFallbackPalette = "#f2c500,#e0408a,#00a3e0,#262626,#f4f4f4";

[[noreturn]] void fail(std::string_view key, const std::string& message) {
    throw InputError("setting '" + std::string(key) + "': " + message);
}

std::string shown(double value) {
    std::string text = std::to_string(value);
    while (!text.empty() && text.back() == '0')
        text.pop_back();
    if (!text.empty() && text.back() == '.')
        text.pop_back();
    return text;
}

std::string trimmed(std::string_view text) {
    const auto first = text.find_first_not_of(" \t\r\n");
    if (first == std::string_view::npos)
        return "";
    const auto last = text.find_last_not_of(" \t\r\n");
    return std::string(text.substr(first, last - first + 1));
}

MixingMode parseMode(const Settings& s) {
    const std::string text = s.text(key::mixing_mode);
    if (text == "single")
        return MixingMode::Single;
    if (text == "dual")
        return MixingMode::Dual;
    if (text == "gradient")
        return MixingMode::Gradient;
    if (text == "color")
        return MixingMode::Color;
    fail("mixing_mode", "unknown mode '" + text + "' (single, dual, gradient or color)");
}

MixDialectKind parseDialect(const Settings& s) {
    const std::string text = s.text(key::mixing_dialect);
    for (const DialectEntry& d : kDialects) {
        if (text == d.name)
            return d.kind;
    }
    std::string names;
    for (const DialectEntry& d : kDialects)
        names += (names.empty() ? "" : ", ") + std::string(d.name);
    fail("mixing_dialect", "unknown dialect '" + text + "' (one of " + names + ")");
}

void checkChannels(const Settings& s, const MixingOutput& out) {
    if (out.channels < 1 || out.channels > kMaxMixChannels)
        fail("mixing_channels",
             std::to_string(out.channels) + " is outside 1.." + std::to_string(kMaxMixChannels));
    const long long extruders = s.integer(key::machine_extruder_count);
    if (extruders > 1 && out.channels > extruders)
        fail("mixing_channels", std::to_string(out.channels) + " channels, but the printer has " +
                                    std::to_string(extruders) + " (machine_extruder_count)");
    const bool two_axes = out.dialect == MixDialectKind::EbAxes || out.dialect == MixDialectKind::KlipperB;
    if (out.mode == MixingMode::Color && out.channels < 2)
        fail("mixing_channels", "color mode mixes 2 to 5 channels, not " + std::to_string(out.channels));
    if (two_axes && out.channels != 2)
        fail("mixing_channels", std::to_string(out.channels) + " channels, but dialect " +
                                    dialectName(out.dialect) + " drives exactly 2 (E and B)");
}

std::vector<GradientStop> twoStopGradient(const Settings& s, int channels) {
    const double start = s.number(key::mixing_gradient_start);
    const double end = s.number(key::mixing_gradient_end);
    if (start > end)
        fail("mixing_gradient_start", shown(start) + " is above mixing_gradient_end " + shown(end));
    if (channels < 2)
        fail("mixing_channels", "a gradient from A to B needs 2 channels, not " + std::to_string(channels));
    return {{start, MixVector::only(0, channels)}, {end, MixVector::only(1, channels)}};
}

}  // namespace

const char* dialectName(MixDialectKind kind) {
    for (const DialectEntry& d : kDialects) {
        if (d.kind == kind)
            return d.name;
    }
    return "?";
}

MixingOutput parseMixingOutput(const Settings& global) {
    MixingOutput out;
    out.mode = parseMode(global);
    if (!out.enabled())
        return out;
    out.dialect = parseDialect(global);
    out.channels = static_cast<int>(global.integer(key::mixing_channels));
    checkChannels(global, out);
    const long long steps = global.integer(key::mixing_resolution);
    if (steps < 1 || steps > 1'000'000)
        fail("mixing_resolution", std::to_string(steps) + " steps is outside 1..1000000");
    out.resolution_steps = static_cast<int>(steps);
    const long long tool = global.integer(key::mixing_tool);
    if (tool < 0 || tool > 255)
        fail("mixing_tool", std::to_string(tool) + " is outside 0..255");
    out.tool = static_cast<int>(tool);
    out.klipper_stepper = trimmed(global.text(key::mixing_klipper_stepper));
    if (out.dialect == MixDialectKind::KlipperB && out.klipper_stepper.empty())
        fail("mixing_klipper_stepper", "empty: the [manual_stepper] name is needed to zero axis B");
    return out;
}

bool relativeExtrusion(const Settings& global) {
    return global.boolean(key::relative_extrusion) || parseMixingOutput(global).forcesRelativeExtrusion();
}

MixVector parseMixRatio(std::string_view key, std::string_view text, int channels) {
    MixVector mix;
    mix.channels = channels;
    int count = 0;
    std::size_t start = 0;
    while (true) {
        const std::size_t colon = text.find(':', start);
        const std::string part =
            trimmed(text.substr(start, colon == std::string_view::npos ? colon : colon - start));
        if (count == channels)
            fail(key, "'" + std::string(text) + "' has more ratios than mixing_channels (" +
                          std::to_string(channels) + ")");
        const double share = parseReal(key, part);
        if (share < 0)
            fail(key, "'" + std::string(text) + "' has a negative ratio");
        mix[count++] = share;
        if (colon == std::string_view::npos)
            break;
        start = colon + 1;
    }
    if (std::fabs(mix.sum() - 1.0) > kSumTolerance)
        fail(key, "ratios '" + std::string(text) + "' add up to " + shown(mix.sum()) + ", not 1");
    return mix;
}

namespace {

/// One "height=value" item of a stop list.
struct StopItem {
    double height = 0;
    std::string value;
};

/// "h=v; h=v; …" → its items, heights not decreasing; `form` shows the expected form in errors.
std::vector<StopItem> splitStops(std::string_view key, std::string_view text, std::string_view form) {
    std::vector<StopItem> items;
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t end = text.find(';', start);
        if (end == std::string_view::npos)
            end = text.size();
        const std::string item = trimmed(text.substr(start, end - start));
        start = end + 1;
        if (item.empty())
            continue;
        const std::size_t eq = item.find('=');
        if (eq == std::string::npos)
            fail(key, "stop '" + item + "' is not " + std::string(form));
        StopItem stop{parseReal(key, trimmed(item.substr(0, eq))), item.substr(eq + 1)};
        if (!items.empty() && stop.height < items.back().height)
            fail(key, "heights must not decrease (" + shown(stop.height) + " after " +
                          shown(items.back().height) + ")");
        items.push_back(std::move(stop));
    }
    return items;
}

}  // namespace

std::string ratioText(const MixVector& mix) {
    std::string text;
    for (int c = 0; c < mix.channels; ++c) {
        char share[16];
        std::snprintf(share, sizeof share, "%.4f", mix[c]);
        text += (c ? ":" : "") + std::string(share);
    }
    return text;
}

std::vector<GradientStop> parseGradientStops(std::string_view key, std::string_view text, int channels) {
    std::vector<GradientStop> stops;
    for (const StopItem& item : splitStops(key, text, "height=ratios (e.g. 50=0.5:0.5)"))
        stops.push_back({item.height, parseMixRatio(key, item.value, channels)});
    return stops;
}

namespace {

GradientAxis parseAxis(const Settings& scope) {
    const std::string axis = trimmed(scope.text(key::mixing_gradient_axis));
    if (axis == "z")
        return GradientAxis::Z;
    if (axis == "x")
        return GradientAxis::X;
    if (axis == "y")
        return GradientAxis::Y;
    if (axis == "radial")
        return GradientAxis::Radial;
    fail("mixing_gradient_axis", "unknown axis '" + axis + "' (z, x, y or radial)");
}

}  // namespace

MeshMixing parseMeshMixing(const Settings& scope, const MixingOutput& output, const PigmentModel* colors) {
    MeshMixing m;
    m.mode = output.mode;
    if (!output.enabled())
        return m;
    if (const std::string core = scope.text(key::mixing_core_ratio); !trimmed(core).empty())
        m.core = parseMixRatio("mixing_core_ratio", core, output.channels);
    m.mode = parseMode(scope);           // a model's own mode (e.g. a cutting mesh's region)
    if (m.mode == MixingMode::Single) {  // within a mixed print: the first filament alone
        m.mode = MixingMode::Dual;
        m.fixed = parseMixRatio("mixing_mode", "1", output.channels);
        return m;
    }
    const std::string unit = scope.text(key::mixing_gradient_unit);
    if (unit == "percent")
        m.unit = HeightUnit::Percent;
    else if (unit == "mm")
        m.unit = HeightUnit::Millimetres;
    else
        fail("mixing_gradient_unit", "unknown unit '" + unit + "' (percent or mm)");
    m.axis = parseAxis(scope);
    if (m.mode == MixingMode::Dual) {
        m.fixed = parseMixRatio("mixing_ratio", scope.text(key::mixing_ratio), output.channels);
        return m;
    }
    if (m.mode == MixingMode::Color) {
        if (!colors)
            throw InternalError("color mode needs the pigment model of mixing_channel_colors");
        m.colors.push_back(parseTargetColor(scope, *colors));
        m.fixed = m.colors.back().solution.mix;
        return m;
    }
    const std::string color_stops = scope.text(key::mixing_gradient_colors);
    if (!trimmed(color_stops).empty() && colors) {
        m.stops = parseGradientColors(color_stops, *colors, m.colors);
        return m;
    }
    const std::string stops = scope.text(key::mixing_gradient_stops);
    m.stops = trimmed(stops).empty() ? twoStopGradient(scope, output.channels)
                                     : parseGradientStops("mixing_gradient_stops", stops, output.channels);
    if (m.stops.empty())
        fail("mixing_gradient_stops", "no stop in '" + stops + "'");
    return m;
}

SolvedColor parseTargetColor(const Settings& scope, const PigmentModel& colors) {
    SolvedColor solved;
    solved.target = parseHexColor("setting 'mixing_target_color'", scope.text(key::mixing_target_color));
    solved.solution = solveColor(colors, solved.target);
    return solved;
}

std::vector<GradientStop> parseGradientColors(std::string_view text, const PigmentModel& colors,
                                              std::vector<SolvedColor>& solved) {
    constexpr std::string_view kKey = "mixing_gradient_colors";
    std::vector<GradientStop> stops;
    for (const StopItem& item : splitStops(kKey, text, "height=#rrggbb (e.g. 50=#ff8000)")) {
        SolvedColor color;
        color.target = parseHexColor("setting 'mixing_gradient_colors'", item.value);
        color.solution = solveColor(colors, color.target);
        stops.push_back({item.height, color.solution.mix});
        solved.push_back(color);
    }
    if (stops.empty())
        fail(kKey, "no stop in '" + std::string(text) + "'");
    return stops;
}

MixVector parseRaftMix(const Settings& global, const MixingOutput& output) {
    return parseMixRatio("mixing_raft_ratio", global.text(key::mixing_raft_ratio), output.channels);
}

MixVector parseSupportMix(const Settings& global, const MixingOutput& output) {
    return parseMixRatio("mixing_support_ratio", global.text(key::mixing_support_ratio), output.channels);
}

double parseChamberVolumeMm3(const Settings& global) {
    const double volume = parseReal("mixing_chamber_volume", global.text(key::mixing_chamber_volume));
    if (volume < 0)
        fail("mixing_chamber_volume", shown(volume) + " mm³ is negative");
    return volume;
}

ChamberSpec parseChamberSpec(const Settings& global) {
    ChamberSpec spec;
    spec.volume_mm3 = parseChamberVolumeMm3(global);
    const long long stages = global.integer(key::mixing_chamber_stages);
    if (stages < 1 || stages > 200)
        fail("mixing_chamber_stages", std::to_string(stages) + " is outside 1..200");
    spec.stages = static_cast<int>(stages);
    return spec;
}

double parseTransitionTolerance(const Settings& global) {
    const double tolerance =
        parseReal("mixing_transition_tolerance", global.text(key::mixing_transition_tolerance));
    if (!(tolerance > 0 && tolerance <= 1))
        fail("mixing_transition_tolerance",
             shown(tolerance) + " is outside (0, 1] (a share: 0.1 = within 10 %)");
    return tolerance;
}

bool parsePurgeTower(const Settings& global) {
    const std::string text = trimmed(global.text(key::mixing_purge_tower_enable));
    if (text != "true" && text != "false" && text != "True" && text != "False")
        fail("mixing_purge_tower_enable", "'" + text + "' is not true or false");
    return text == "true" || text == "True";
}

std::vector<Rgb> parseChannelColors(const Settings& global, int channels) {
    const std::string defaults(kFallbackPalette);
    const std::string given = global.text(key::mixing_channel_colors);
    auto nth = [](const std::string& list, int index) {
        std::size_t start = 0;
        for (int i = 0; i < index && start != std::string::npos; ++i) {
            start = list.find(',', start);
            start = start == std::string::npos ? start : start + 1;
        }
        if (start == std::string::npos)
            return std::string();
        return trimmed(list.substr(start, list.find(',', start) - start));
    };
    std::vector<Rgb> colors;
    for (int c = 0; c < channels; ++c) {
        std::string hex = nth(given, c);
        if (hex.empty())
            hex = nth(defaults, c);
        if (hex.size() != 7 || hex[0] != '#' ||
            hex.find_first_not_of("0123456789abcdefABCDEF", 1) != std::string::npos)
            fail("mixing_channel_colors", "'" + hex + "' is not a colour like #ff8800");
        Rgb rgb{};
        for (int k = 0; k < 3; ++k)
            rgb[static_cast<std::size_t>(k)] = static_cast<std::uint8_t>(
                std::stoi(hex.substr(1 + 2 * static_cast<std::size_t>(k), 2), nullptr, 16));
        colors.push_back(rgb);
    }
    return colors;
}

}  // namespace mixengine
