// `mixengine orient <parts...>`: the dual-nozzle orientation pass on its own (orient/Orienter.h).
// Prints the best rotation, V before and after and the time taken; --report, --plot and --write
// save the JSON report, the V map as PNG and the rotated parts as binary STL.
// Exactly two parts are optimised (A = the first, B = the second; files or the parts of one
// multi-part file). One part only is not an error: the command says there is nothing to optimise
// and exits with 0.
#include <algorithm>
#include <array>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string_view>

#include "common/Error.h"
#include "common/Log.h"
#include "communication/CommandLineParser.h"
#include "communication/Commands.h"
#include "communication/OutputFile.h"
#include "mesh/build/MeshBuilder.h"
#include "orient/MeshRotation.h"
#include "orient/OrientReport.h"
#include "orient/OrientSettings.h"
#include "orient/VMapPng.h"
#include "pipeline/Scene.h"

namespace mixengine {
namespace {

struct OrientArgs {
    std::vector<std::filesystem::path> files;
    std::optional<Vec3> offset_mm;
    std::string machine;
    SettingValues settings;
    std::vector<std::pair<std::string, std::string>> flags;  ///< option name, value (applied in order)
    std::filesystem::path report, plot, write_dir;
    int verbosity = 0;
};

Vec3 parseOffset(const std::string& text) {
    double x = 0, y = 0;
    char comma = 0, extra = 0;
    if (std::sscanf(text.c_str(), "%lf %c %lf %c", &x, &comma, &y, &extra) != 3 || comma != ',')
        throw InputError("orient: --offset '" + text + "' is not X,Y in millimetres");
    return {x, y, 0};
}

/// The options passed on to applyFlags() with their value ("-m4" is also accepted as "-m 4").
constexpr std::array<std::string_view, 7> kFlagOptions = {
    "--method", "--measure", "--objective", "--resolution", "--verify", "--grid-step", "-m"};

/// The output path an option names (--report, --plot, --write), or nullptr.
std::filesystem::path* outputPath(OrientArgs& o, const std::string& option) {
    if (option == "--report")
        return &o.report;
    if (option == "--plot")
        return &o.plot;
    return option == "--write" ? &o.write_dir : nullptr;
}

/// Applies an option with a value; false when `w` is not one. `value` takes the next word.
template <class NextValue>
bool valueOption(OrientArgs& o, const std::string& w, NextValue&& value) {
    if (w == "--offset") {
        o.offset_mm = parseOffset(value());
    } else if (w == "-j") {
        o.machine = value();
    } else if (w == "-s") {
        o.settings.insert(splitSettingArgument(value()));
    } else if (std::filesystem::path* path = outputPath(o, w)) {
        *path = value();
    } else if (std::find(kFlagOptions.begin(), kFlagOptions.end(), w) != kFlagOptions.end()) {
        o.flags.emplace_back(w, value());
    } else {
        return false;
    }
    return true;
}

/// Applies an option or file name without a value of its own.
void plainWord(OrientArgs& o, const std::string& w) {
    if (w.starts_with("-m") && w.size() > 2) {
        o.flags.emplace_back("-m", w.substr(2));
    } else if (w == "-v" || w == "-vv") {
        o.verbosity += static_cast<int>(w.size()) - 1;
    } else if (w.starts_with("-")) {
        throw InputError("orient: unknown option '" + w + "' (see mixengine help)");
    } else {
        o.files.emplace_back(w);
    }
}

OrientArgs parseArgs(const Words& args) {
    OrientArgs o;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& w = args[i];
        auto value = [&]() -> const std::string& {
            if (i + 1 >= args.size())
                throw InputError("orient: " + w + " needs a value");
            return args[++i];
        };
        if (!valueOption(o, w, value))
            plainWord(o, w);
    }
    return o;
}

int integerFlag(const std::string& name, const std::string& text) {
    try {
        std::size_t used = 0;
        const int v = std::stoi(text, &used);
        if (used == text.size())
            return v;
    } catch (const std::exception&) {
    }
    throw InputError("orient: " + name + " '" + text + "' is not an integer");
}

orient::OrientOptions applyFlags(orient::OrientOptions o, const OrientArgs& args) {
    for (const auto& [name, text] : args.flags) {
        if (name == "--method") {
            o.method = orient::parseMethod(text, "orient --method");
        } else if (name == "--measure") {
            o.measure = orient::parseMeasure(text, "orient --measure");
        } else if (name == "--objective") {
            o.objective = orient::parseObjective(text, "orient --objective");
        } else if (name == "--resolution") {
            o.resolution = integerFlag(name, text);
        } else if (name == "--verify") {
            o.verify = integerFlag(name, text);
        } else if (name == "--grid-step") {
            o.grid_step_deg = integerFlag(name, text);
        } else {
            o.threads = integerFlag(name, text);
        }
    }
    if (o.resolution < 8 || o.resolution > 1024 || o.verify < 0 || o.grid_step_deg < 1 ||
        o.grid_step_deg > 90)
        throw InputError("orient: --resolution must be 8..1024, --verify ≥ 0, --grid-step 1..90");
    return o;
}

std::vector<Mesh> loadParts(const OrientArgs& args, Log& log) {
    std::vector<Mesh> parts;
    for (const auto& file : args.files) {
        std::vector<std::string> warnings;
        const std::vector<TriangleSoup> soups = readModelFile(file, warnings);
        for (const std::string& w : warnings)
            log.warning(w);
        for (const TriangleSoup& soup : soups) {
            Mesh mesh = buildMesh(soup, Matrix3{});
            mesh.name = soups.size() == 1 ? file.string() : file.string() + "#" + soup.name;
            if (mesh.faces.empty())
                throw InputError(mesh.name + ": no facets left after cleaning");
            parts.push_back(std::move(mesh));
        }
    }
    return parts;
}

void writeOutputs(const OrientArgs& args, const orient::OrientResult& result, std::vector<Mesh>& parts,
                  std::ostream& out) {
    const orient::PartNames names{parts[0].name, parts[1].name};
    if (!args.report.empty()) {
        writeFileAtomically(args.report, orient::resultJson(result, names).dump(1) + "\n");
        out << "report: " << args.report.string() << '\n';
    }
    if (!args.plot.empty()) {
        writeFileAtomically(args.plot, orient::renderVMapPng(result.map, result.angles));
        out << "plot: " << args.plot.string() << '\n';
    }
    if (!args.write_dir.empty()) {
        orient::rotateTogether({&parts[0], &parts[1]}, result.rotation, result.centre_mm);
        std::filesystem::create_directories(args.write_dir);
        for (const Mesh& mesh : parts) {
            const auto path =
                args.write_dir / (std::filesystem::path(mesh.name).stem().string() + "_oriented.stl");
            writeFileAtomically(path, orient::binaryStl(mesh));
            out << "wrote " << path.string() << '\n';
        }
    }
}

}  // namespace

int runOrientCommand(const Words& words, std::ostream& out, std::ostream& err) {
    const OrientArgs args = parseArgs(words);
    Log log(err, args.verbosity);
    if (args.files.empty())
        throw InputError("orient: give the parts, e.g. mixengine orient a.stl b.stl --offset 35,0");
    orient::OrientOptions options;
    std::optional<Vec3> offset = args.offset_mm;
    if (!args.machine.empty()) {
        SliceRequest request;
        request.definition = args.machine;
        request.user.global = args.settings;
        const Scene scene = prepareSettings(request);
        options = orient::optionsFromSettings(scene.machine.global);
        if (!offset)
            offset = orient::nozzleOffsetMm(scene.machine.extruders);
    }
    options = applyFlags(options, args);
    std::vector<Mesh> parts = loadParts(args, log);
    if (parts.size() == 1) {
        out << "nothing to optimise: only one part (" << parts[0].name
            << "); the orientation pass needs two parts, one per nozzle\n";
        if (!args.report.empty())
            writeFileAtomically(
                args.report, nlohmann::json{{"status", "nothing_to_optimise"}, {"parts", 1}}.dump() + "\n");
        return 0;
    }
    if (parts.size() > 2)
        throw InputError("orient: " + std::to_string(parts.size()) +
                         " parts given; give exactly two (A for extruder 0, B for extruder 1)");
    if (!offset)
        throw InputError(
            "orient: no nozzle offset: give --offset X,Y (mm) or -j with a two-extruder machine");
    const orient::OrientResult result =
        orient::optimiseOrientation(parts[0], parts[1], *offset, options, log);
    out << orient::resultText(result, {parts[0].name, parts[1].name});
    writeOutputs(args, result, parts, out);
    return 0;
}

}  // namespace mixengine
