#pragma once
// A machine as its definition files describe it: the global settings (fdmprinter + the machine's
// inherits chain, with every `overrides` applied) and one entry per extruder train
// (`machine_extruder_trains` metadata → extruder definitions inheriting fdmextruder).
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "settings/SettingDefinition.h"

namespace mixengine {

struct ExtruderDefinition {
    std::string id;                  ///< definition id, e.g. "creality_base_extruder_0"
    int position = 0;                ///< extruder_nr
    SettingDefinitionMap overrides;  ///< what this extruder's chain changes relative to the global one
    /// Keys of `overrides` that only an `overrides` entry names, no `settings` tree of the chain
    /// (e.g. machine_nozzle_head_distance in ultimaker_s5_extruder_left). CuraEngine's -j applies
    /// them; Cura's frontend (Uranium's DefinitionContainer) ignores them ("Unable to override").
    std::set<std::string, std::less<>> undeclared;
};

struct DefinitionSet {
    std::string machine_id;                    ///< e.g. "creality_ender3" or "fdmprinter"
    std::vector<std::filesystem::path> files;  ///< every file read, most derived first
    SettingDefinitionMap settings;
    std::vector<ExtruderDefinition> extruders;    ///< ordered by position; at least one
    std::map<std::string, std::string> metadata;  ///< scalar metadata values (str() form)

    const SettingDefinition* find(std::string_view key) const {
        auto it = settings.find(key);
        return it == settings.end() ? nullptr : &it->second;
    }
};

/// Where definitions are looked for: CURA_ENGINE_SEARCH_PATH (':' or ';' separated), then the
/// project's own settings/ folder, then Cura's installed resources (definitions and extruders).
std::vector<std::filesystem::path> defaultSearchPath(const char* env_search_path);

/// Loads `name_or_path` (a path to a .def.json, or an id like "creality_ender3") with its whole
/// inherits chain and its extruder trains. Throws InputError naming the file at fault.
DefinitionSet loadDefinitionSet(const std::string& name_or_path,
                                const std::vector<std::filesystem::path>& search);

}  // namespace mixengine
