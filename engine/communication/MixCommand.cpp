// `mixengine mix`: the colour solver on its own. --colors names the filament colours (2 to 5),
// --target the colour wanted: prints the ratios, the predicted colour and its ΔE00 to the target
// (mixing/color/ColorSolver.h). --ratio instead of --target prints the colour a given mix is predicted
// to print.
#include <cstdio>
#include <optional>

#include "common/Error.h"
#include "communication/Commands.h"
#include "mixing/color/ColorSolver.h"
#include "mixing/setup/MixingSettings.h"

namespace mixengine {
namespace {

struct MixArguments {
    std::vector<Rgb> colors;
    std::optional<Rgb> target;
    std::string ratio;
};

std::vector<Rgb> parseColorList(const std::string& text) {
    const std::vector<Rgb> colors = parseHexColorList("--colors", text);
    if (colors.size() < 2 || colors.size() > static_cast<std::size_t>(kMaxMixChannels))
        throw InputError("--colors: " + std::to_string(colors.size()) + " colours given, 2 to " +
                         std::to_string(kMaxMixChannels) + " are mixed");
    return colors;
}

MixArguments parseMixArguments(const Words& args) {
    MixArguments parsed;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& word = args[i];
        if (word != "--colors" && word != "--target" && word != "--ratio")
            throw InputError("mix: unknown argument '" + word + "' (--colors, --target or --ratio)");
        if (i + 1 == args.size())
            throw InputError(word + ": a value is needed");
        const std::string& value = args[++i];
        if (word == "--colors")
            parsed.colors = parseColorList(value);
        else if (word == "--target")
            parsed.target = parseHexColor("--target", value);
        else
            parsed.ratio = value;
    }
    if (parsed.colors.empty())
        throw InputError("mix: --colors is needed (e.g. --colors \"#00ffff,#ff00ff,#ffff00,#ffffff\")");
    if (parsed.target.has_value() == !parsed.ratio.empty())
        throw InputError("mix: give either --target \"#rrggbb\" or --ratio a:b:...");
    return parsed;
}

}  // namespace

int runMixCommand(const Words& args, std::ostream& out, std::ostream&) {
    const MixArguments parsed = parseMixArguments(args);
    const PigmentModel model(parsed.colors);
    out << "channels  ";
    for (const Rgb& color : parsed.colors)
        out << ' ' << hexOf(color);
    out << '\n';
    if (!parsed.target) {
        const MixVector mix = parseMixRatio("--ratio", parsed.ratio, static_cast<int>(parsed.colors.size()));
        out << "ratios     " << ratioText(mix) << '\n'
            << "predicted  " << hexOf(model.predictRgb(mix)) << '\n';
        return 0;
    }
    const ColorSolution solution = solveColor(model, *parsed.target);
    char de[64];
    std::snprintf(de, sizeof de, "%.2f", solution.delta_e00);
    out << "target     " << hexOf(*parsed.target) << '\n'
        << "ratios     " << ratioText(solution.mix) << '\n'
        << "predicted  " << hexOf(solution.predicted_rgb) << '\n'
        << "dE00       " << de
        << (solution.delta_e00 > kGamutWarningDeltaE00
                ? "  (outside the mixable gamut: the nearest mixable colour)"
                : "")
        << '\n';
    return 0;
}

}  // namespace mixengine
