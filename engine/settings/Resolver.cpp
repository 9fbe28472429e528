#include "settings/Resolver.h"

#include <algorithm>

#include "common/Error.h"
#include "settings/ValueParse.h"

namespace mixengine {
namespace {

SettingValues definitionValues(const SettingDefinitionMap& definitions) {
    SettingValues values;
    for (const auto& [key, def] : definitions) values.emplace(key, def.default_value);
    return values;
}

int extruderCount(const DefinitionSet& definitions, const Settings& global, const UserSettings& user) {
    int count = static_cast<int>(definitions.extruders.size());
    if (global.has("machine_extruder_count")) {
        count = std::max(count, static_cast<int>(global.integer("machine_extruder_count")));
    }
    if (!user.extruders.empty()) count = std::max(count, user.extruders.rbegin()->first + 1);
    return std::clamp(count, 1, 16);
}

const ExtruderDefinition* extruderDefinition(const DefinitionSet& definitions, int position) {
    for (const ExtruderDefinition& e : definitions.extruders) {
        if (e.position == position) return &e;
    }
    return nullptr;
}

/// The extruder a limit_to_extruder expression names, or -1 for none. Until formulas are
/// evaluated (settings/formula), a bare setting key or an integer is understood.
int limitTarget(const SettingDefinition& def, const Settings& scope) {
    if (!def.limit_to_extruder) return -1;
    const std::string& expression = *def.limit_to_extruder;
    if (scope.has(expression)) return static_cast<int>(parseInteger(def.key, scope.text(expression)));
    double number = 0;
    try {
        number = parseReal(def.key, expression);
    } catch (const InputError&) {
        return -1;
    }
    return static_cast<int>(number);
}

}  // namespace

ResolvedMachine resolveMachine(const DefinitionSet& definitions, const UserSettings& user) {
    SettingValues global_values = definitionValues(definitions.settings);
    for (const auto& [key, value] : user.global) global_values[key] = value;
    ResolvedMachine machine;
    machine.global = Settings("global settings", std::move(global_values));

    const int count = extruderCount(definitions, machine.global, user);
    for (int nr = 0; nr < count; ++nr) {
        SettingValues values = definitionValues(definitions.settings);
        if (const ExtruderDefinition* def = extruderDefinition(definitions, nr)) {
            for (const auto& [key, setting] : def->overrides) values[key] = setting.default_value;
        }
        for (const auto& [key, value] : user.global) values[key] = value;
        values["extruder_nr"] = std::to_string(nr);
        if (auto it = user.extruders.find(nr); it != user.extruders.end()) {
            for (const auto& [key, value] : it->second) values[key] = value;
        }
        machine.extruders.emplace_back("extruder " + std::to_string(nr), std::move(values));
    }
    return machine;
}

Settings resolveMeshGroup(const ResolvedMachine& machine, const SettingValues& group_user, int group_index) {
    return machine.global.with("mesh group " + std::to_string(group_index), group_user);
}

Settings resolveMesh(const DefinitionSet& definitions, const ResolvedMachine& machine, const Settings& group,
                     const SettingValues& mesh_user, int default_extruder, const std::string& mesh_name) {
    int extruder = default_extruder;
    if (auto it = mesh_user.find("extruder_nr"); it != mesh_user.end()) {
        extruder = static_cast<int>(parseInteger("extruder_nr", it->second));
    }
    const int count = static_cast<int>(machine.extruders.size());
    if (extruder < 0 || extruder >= count) {
        throw InputError("mesh '" + mesh_name + "': extruder_nr " + std::to_string(extruder) +
                         " does not exist (the machine has " + std::to_string(count) + " extruder trains)");
    }
    const Settings& train = machine.extruders[static_cast<std::size_t>(extruder)];
    SettingValues values = train.all();
    // Group-level user values sit between the train and the mesh.
    for (const auto& [key, value] : group.all()) {
        if (!machine.global.has(key) || machine.global.text(key) != value) values[key] = value;
    }
    for (const auto& [key, def] : definitions.settings) {
        if (mesh_user.count(key)) continue;
        const int target = limitTarget(def, train);
        if (target >= 0 && target < count) {
            const Settings& limited = machine.extruders[static_cast<std::size_t>(target)];
            if (limited.has(key)) values[key] = limited.text(key);
        }
    }
    for (const auto& [key, value] : mesh_user) values[key] = value;
    values["extruder_nr"] = std::to_string(extruder);
    return Settings("mesh '" + mesh_name + "'", std::move(values));
}

}  // namespace mixengine
