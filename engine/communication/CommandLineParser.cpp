#include "communication/CommandLineParser.h"

#include <cctype>

#include "common/Error.h"
#include "settings/Settings.h"

namespace mixengine {
namespace {

enum class Focus { Global, Group, Extruder, Mesh };

struct ParseState {
    ParsedSliceArgs parsed;
    Focus focus = Focus::Global;
    int extruder = 0;

    SliceRequest& request() { return parsed.request; }
    MeshGroupInput& group() { return request().groups.back(); }

    SettingValues& focusValues() {
        switch (focus) {
            case Focus::Group:
                return group().settings;
            case Focus::Extruder:
                return request().user.extruders[extruder];
            case Focus::Mesh:
                return group().meshes.back().settings;
            case Focus::Global:
                break;
        }
        return request().user.global;
    }

    /// The mesh_rotation_matrix text in force: the focus first, then outwards.
    const std::string* rotationText() {
        const SettingValues* chain[] = {&focusValues(), &group().settings, &request().user.global};
        for (const SettingValues* values : chain) {
            if (auto it = values->find("mesh_rotation_matrix"); it != values->end())
                return &it->second;
        }
        return nullptr;
    }
};

const std::string& nextWord(const std::vector<std::string>& args, std::size_t& i, const std::string& flag) {
    if (i + 1 >= args.size())
        throw InputError("option " + flag + " needs a value");
    return args[++i];
}

int parseDigits(const std::string& text, const std::string& flag) {
    if (text.empty())
        throw InputError("option " + flag + " needs a number");
    for (char c : text) {
        if (!std::isdigit(static_cast<unsigned char>(c)))
            throw InputError("option " + flag + ": '" + text + "' is not a number");
    }
    if (text.size() > 3)
        throw InputError("option " + flag + ": '" + text + "' is out of range");
    return std::stoi(text);
}

void loadModel(ParseState& state, const std::string& path) {
    MeshInput mesh;
    mesh.name = path;
    mesh.file = path;
    mesh.default_extruder = state.extruder;
    if (const std::string* text = state.rotationText()) {
        mesh.transform =
            Settings("command line", {{"mesh_rotation_matrix", *text}}).matrix3(key::mesh_rotation_matrix);
    }
    state.group().meshes.push_back(std::move(mesh));
    state.focus = Focus::Mesh;
}

// --- profile selection (settings/profiles/ProfileSelector.h) ---
/// Handles --variant/--material/--quality/--intent NAME and --profiles; false for other words.
bool applyProfileOption(ProfileSelection& profiles, const std::vector<std::string>& args, std::size_t& i) {
    const std::string& word = args[i];
    std::string* target = word == "--variant"    ? &profiles.variant
                          : word == "--material" ? &profiles.material
                          : word == "--quality"  ? &profiles.quality
                          : word == "--intent"   ? &profiles.intent
                                                 : nullptr;
    if (!target && word != "--profiles")
        return false;
    if (target)
        *target = nextWord(args, i, word);
    profiles.enabled = true;
    return true;
}
// --- end of profile selection ---

}  // namespace

std::pair<std::string, std::string> splitSettingArgument(const std::string& word) {
    auto eq = word.find('=');
    if (eq == std::string::npos || eq == 0) {
        throw InputError("-s '" + word + "': expected key=value");
    }
    std::string value = word.substr(eq + 1);
    if (value.size() >= 2 && value.front() == '"' && value.back() == '"')
        value = value.substr(1, value.size() - 2);
    return {word.substr(0, eq), value};
}

ParsedSliceArgs parseSliceArguments(const std::vector<std::string>& args) {
    ParseState state;
    state.request().groups.emplace_back();
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& word = args[i];
        if (word == "-v" || word == "-vv") {
            state.request().verbosity += static_cast<int>(word.size()) - 1;
        } else if (word == "-p") {
            state.request().progress = true;
        } else if (word.rfind("-m", 0) == 0) {
            state.request().threads =
                parseDigits(word.size() > 2 ? word.substr(2) : nextWord(args, i, word), "-m");
        } else if (word == "-j") {
            state.request().definition = nextWord(args, i, word);
        } else if (word == "-s") {
            auto [key, value] = splitSettingArgument(nextWord(args, i, word));
            state.focusValues()[key] = value;
        } else if (word.rfind("-s", 0) == 0 && word.find('=') != std::string::npos) {
            auto [key, value] = splitSettingArgument(word.substr(2));
            state.focusValues()[key] = value;
        } else if (word == "-g") {
            state.focus = Focus::Group;
        } else if (word.rfind("-e", 0) == 0) {
            state.extruder = parseDigits(word.substr(2), "-e");
            state.focus = Focus::Extruder;
            state.request().user.extruders[state.extruder];
        } else if (word == "-l") {
            loadModel(state, nextWord(args, i, word));
        } else if (word == "--next") {
            state.request().groups.emplace_back();
            state.focus = Focus::Group;
        } else if (word == "-o") {
            state.request().output = nextWord(args, i, word);
        } else if (applyProfileOption(state.request().profiles, args, i)) {
            // --variant / --material / --quality / --intent NAME, --profiles (settings/profiles/)
        } else if (word == "--dump-layers") {
            state.parsed.dump_layers_dir = nextWord(args, i, word);
        } else if (word == "--preview") {
            state.parsed.preview_png = nextWord(args, i, word);
        } else {
            throw InputError("unknown option '" + word + "' (see 'mixengine help')");
        }
    }
    return std::move(state.parsed);
}

}  // namespace mixengine
