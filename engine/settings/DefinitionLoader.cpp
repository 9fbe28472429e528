// Loading of Cura definition files (*.def.json): the inherits chain, the setting tree, overrides,
// metadata, and the extruder trains named in `machine_extruder_trains`.
#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "common/Error.h"
#include "settings/DefinitionSet.h"
#include "settings/JsonText.h"

namespace mixengine {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr const char* kCuraResources = "/usr/share/cura/resources";

json readJsonFile(const fs::path& file) {
    std::ifstream in(file);
    if (!in)
        throw InputError(file.string() + ": cannot open definition file");
    try {
        return json::parse(in);
    } catch (const json::parse_error& e) {
        throw InputError(file.string() + ": invalid JSON: " + e.what());
    }
}

fs::path findDefinition(const std::string& name_or_path, const std::vector<fs::path>& search) {
    fs::path direct(name_or_path);
    if (std::error_code ec; fs::is_regular_file(direct, ec))
        return direct;
    std::string id = direct.filename().string();
    const std::string suffix = ".def.json";
    if (id.size() > suffix.size() && id.ends_with(suffix))
        id.resize(id.size() - suffix.size());
    for (const fs::path& dir : search) {
        fs::path candidate = dir / (id + suffix);
        if (std::error_code ec; fs::is_regular_file(candidate, ec))
            return candidate;
    }
    throw InputError(name_or_path + ": definition not found (searched CURA_ENGINE_SEARCH_PATH and " +
                     std::string(kCuraResources) + ")");
}

std::optional<std::string> optionalText(const json& node, const char* property) {
    auto it = node.find(property);
    if (it == node.end())
        return std::nullopt;
    return jsonToPythonText(*it);
}

void applyProperties(SettingDefinition& def, const json& node) {
    if (auto it = node.find("type"); it != node.end())
        def.type = it->get<std::string>();
    if (auto it = node.find("default_value"); it != node.end())
        def.default_value = jsonToPythonText(*it);
    if (auto v = optionalText(node, "value"))
        def.value_formula = v;
    if (auto v = optionalText(node, "resolve"))
        def.resolve_formula = v;
    if (auto v = optionalText(node, "limit_to_extruder"))
        def.limit_to_extruder = v;
    if (auto v = optionalText(node, "enabled"))
        def.enabled_formula = v;
    if (auto v = optionalText(node, "minimum_value"))
        def.minimum_value = v;
    if (auto v = optionalText(node, "maximum_value"))
        def.maximum_value = v;
    if (auto it = node.find("unit"); it != node.end() && it->is_string())
        def.unit = it->get<std::string>();
    if (auto it = node.find("settable_per_mesh"); it != node.end() && it->is_boolean())
        def.settable_per_mesh = it->get<bool>();
    if (auto it = node.find("settable_per_extruder"); it != node.end() && it->is_boolean())
        def.settable_per_extruder = it->get<bool>();
    if (auto it = node.find("options"); it != node.end() && it->is_object()) {
        def.enum_options.clear();
        for (const auto& [option, label] : it->items())
            def.enum_options.push_back(option);
    }
}

void collectSettings(const json& tree, SettingDefinitionMap& out) {
    for (const auto& [key, node] : tree.items()) {
        if (!node.is_object())
            continue;
        if (node.value("type", "") != "category") {
            SettingDefinition& def = out[key];
            def.key = key;
            applyProperties(def, node);
        }
        if (auto children = node.find("children"); children != node.end())
            collectSettings(*children, out);
    }
}

void collectMetadata(const json& metadata, std::map<std::string, std::string>& out) {
    for (const auto& [key, value] : metadata.items()) {
        if (!value.is_object())
            out[key] = jsonToPythonText(value);
    }
}

/// The chain of files from the root (fdmprinter / fdmextruder) to `leaf`.
std::vector<std::pair<fs::path, json>> loadChain(const std::string& leaf,
                                                 const std::vector<fs::path>& search) {
    std::vector<std::pair<fs::path, json>> chain;
    std::set<fs::path> seen;
    std::string next = leaf;
    while (!next.empty()) {
        fs::path file = findDefinition(next, search);
        if (!seen.insert(fs::weakly_canonical(file)).second)
            throw InputError(file.string() + ": inherits chain loops back to this file");
        json doc = readJsonFile(file);
        if (!doc.is_object())
            throw InputError(file.string() + ": definition is not a JSON object");
        auto inherits = doc.find("inherits");
        if (inherits != doc.end() && !inherits->is_string())
            throw InputError(file.string() + ": 'inherits' must be a definition id (a string)");
        next = inherits == doc.end() ? std::string() : inherits->get<std::string>();
        chain.emplace_back(file, std::move(doc));
    }
    std::reverse(chain.begin(), chain.end());
    return chain;
}

struct MergedChain {
    SettingDefinitionMap settings;
    std::map<std::string, std::string> metadata;
    json extruder_trains = json::object();
    std::vector<fs::path> files;
    std::set<std::string, std::less<>> undeclared;  ///< overridden keys no file of the chain declares
};

void mergeFile(const fs::path& file, const json& doc, MergedChain& merged) {
    merged.files.insert(merged.files.begin(), file);
    if (auto it = doc.find("settings"); it != doc.end())
        collectSettings(*it, merged.settings);
    if (auto it = doc.find("metadata"); it != doc.end() && it->is_object()) {
        collectMetadata(*it, merged.metadata);
        if (auto trains = it->find("machine_extruder_trains"); trains != it->end())
            merged.extruder_trains = *trains;
    }
    if (auto it = doc.find("overrides"); it != doc.end() && it->is_object()) {
        for (const auto& [key, node] : it->items()) {
            if (!merged.settings.count(key))
                merged.undeclared.insert(key);
            SettingDefinition& def = merged.settings[key];
            def.key = key;
            applyProperties(def, node);
        }
    }
}

void mergeChecked(const fs::path& file, const json& doc, MergedChain& merged) {
    try {
        mergeFile(file, doc, merged);
    } catch (const json::exception& e) {
        throw InputError(file.string() + ": unexpected JSON content: " + e.what());
    }
}

/// MixEngine's own settings (mixing, orientation): every *.def.json in a `mixengine` folder of
/// the search path; for one file name the first folder wins.
std::vector<fs::path> extensionFiles(const std::vector<fs::path>& search) {
    std::map<std::string, fs::path> by_name;
    for (const fs::path& dir : search) {
        std::error_code ec;
        for (const auto& entry : fs::directory_iterator(dir / "mixengine", ec)) {
            const std::string name = entry.path().filename().string();
            if (name.ends_with(".def.json"))
                by_name.emplace(name, entry.path());
        }
    }
    std::vector<fs::path> files;
    for (const auto& [name, path] : by_name)
        files.push_back(path);
    return files;
}

/// Merges the chain root first; when `extensions` is given (machine chains), MixEngine's own
/// settings come right after the root, so that machine definitions can override them.
MergedChain mergeChain(const std::vector<std::pair<fs::path, json>>& chain,
                       const std::vector<fs::path>& extensions = {}) {
    MergedChain merged;
    for (std::size_t i = 0; i < chain.size(); ++i) {
        mergeChecked(chain[i].first, chain[i].second, merged);
        if (i != 0)
            continue;
        for (const fs::path& file : extensions)
            mergeChecked(file, readJsonFile(file), merged);
    }
    return merged;
}

ExtruderDefinition loadExtruder(const std::string& id, int position, const std::vector<fs::path>& search,
                                std::vector<fs::path>& files) {
    MergedChain merged = mergeChain(loadChain(id, search));
    files.insert(files.end(), merged.files.begin(), merged.files.end());
    ExtruderDefinition extruder;
    extruder.id = id;
    extruder.position = position;
    extruder.overrides = std::move(merged.settings);
    extruder.undeclared = std::move(merged.undeclared);
    return extruder;
}

}  // namespace

std::vector<fs::path> defaultSearchPath(const char* env_search_path) {
    std::vector<fs::path> dirs;
    if (env_search_path) {
        std::string list = env_search_path;
        std::size_t start = 0;
        while (start <= list.size()) {
            std::size_t end = list.find_first_of(":;", start);
            if (end == std::string::npos)
                end = list.size();
            if (end > start)
                dirs.emplace_back(list.substr(start, end - start));
            start = end + 1;
        }
    }
#ifdef MIXENGINE_SETTINGS_DIR
    dirs.emplace_back(MIXENGINE_SETTINGS_DIR);
    dirs.emplace_back(fs::path(MIXENGINE_SETTINGS_DIR) / "definitions");
    dirs.emplace_back(fs::path(MIXENGINE_SETTINGS_DIR) / "extruders");
#endif
    dirs.emplace_back(fs::path(kCuraResources) / "definitions");
    dirs.emplace_back(fs::path(kCuraResources) / "extruders");
    return dirs;
}

DefinitionSet loadDefinitionSet(const std::string& name_or_path, const std::vector<fs::path>& search) {
    auto chain = loadChain(name_or_path, search);
    MergedChain merged = mergeChain(chain, extensionFiles(search));
    DefinitionSet set;
    set.machine_id = chain.back().first.filename().string();
    if (set.machine_id.ends_with(".def.json"))
        set.machine_id.resize(set.machine_id.size() - 9);
    set.files = merged.files;
    set.settings = std::move(merged.settings);
    set.metadata = std::move(merged.metadata);

    std::map<int, std::string> trains;
    if (merged.extruder_trains.is_object()) {
        for (const auto& [position, id] : merged.extruder_trains.items()) {
            if (id.is_string())
                trains[std::atoi(position.c_str())] = id.get<std::string>();
        }
    }
    if (trains.empty())
        trains[0] = "fdmextruder";
    for (const auto& [position, id] : trains) {
        set.extruders.push_back(loadExtruder(id, position, search, set.files));
    }
    return set;
}

}  // namespace mixengine
