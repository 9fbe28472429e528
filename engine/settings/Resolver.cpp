#include "settings/Resolver.h"

#include <algorithm>

#include "common/Error.h"
#include "settings/FrontendValues.h"
#include "settings/StackEvaluator.h"
#include "settings/ValueParse.h"

namespace mixengine {
namespace {

int userExtruderCount(const DefinitionSet& definitions, const UserSettings& user) {
    int count = static_cast<int>(definitions.extruders.size());
    if (!user.extruders.empty())
        count = std::max(count, user.extruders.rbegin()->first + 1);
    return count;
}

}  // namespace

ResolvedMachine resolveMachine(const DefinitionSet& definitions, const UserSettings& given_user,
                               const ProfileStack* profiles) {
    const UserSettings user = withCanonicalKeys(given_user);  // seed 001's aliases
    int count = std::clamp(userExtruderCount(definitions, user), 1, 16);
    {
        StackEvaluator probe(definitions, user, count, profiles);
        if (auto declared = probe.value(StackEvaluator::kGlobal, "machine_extruder_count")) {
            if (declared->is<std::int64_t>())
                count = std::clamp(static_cast<int>(declared->as<std::int64_t>()), count, 16);
        }
    }
    StackEvaluator stack(definitions, user, count, profiles);
    ResolvedMachine machine;
    machine.global = Settings("global settings", stack.allText(StackEvaluator::kGlobal));
    for (int nr = 0; nr < count; ++nr) {
        machine.extruders.emplace_back("extruder " + std::to_string(nr),
                                       stack.allText(StackEvaluator::extruderScope(nr)));
    }
    machine.formula_failures = stack.failures();
    return machine;
}

Settings resolveMeshGroup(const ResolvedMachine& machine, const SettingValues& group_user, int group_index) {
    return machine.global.with("mesh group " + std::to_string(group_index), withCanonicalKeys(group_user));
}

Settings resolveMesh(const DefinitionSet& definitions, const UserSettings& given_user,
                     const ResolvedMachine& machine, const Settings& group,
                     const SettingValues& given_mesh_user, int default_extruder, const std::string& mesh_name,
                     const ProfileStack* profiles, std::vector<std::string>* failures) {
    const UserSettings user = withCanonicalKeys(given_user);  // seed 001's aliases
    const SettingValues mesh_user = withCanonicalKeys(given_mesh_user);
    int extruder = default_extruder;
    if (auto it = mesh_user.find("extruder_nr"); it != mesh_user.end()) {
        extruder = static_cast<int>(parseInteger("extruder_nr", it->second));
    }
    const int count = static_cast<int>(machine.extruders.size());
    if (extruder < 0 || extruder >= count) {
        throw InputError("mesh '" + mesh_name + "': extruder_nr " + std::to_string(extruder) +
                         " does not exist (the machine has " + std::to_string(count) + " extruder trains)");
    }
    const std::string scope = "mesh '" + mesh_name + "'";
    SettingValues own = mesh_user;
    own.erase("extruder_nr");
    // Group-level values (-g) sit between the train and the mesh.
    for (const auto& [key, value] : group.all()) {
        if (const std::string* global = machine.global.find(key); global == nullptr || *global != value)
            own.emplace(key, value);
    }
    SettingValues values;
    if (own.empty()) {
        values = machine.extruders[static_cast<std::size_t>(extruder)].all();
    } else {
        StackEvaluator stack(definitions, user, count, profiles);
        values = stack.allText(stack.addMeshScope(own, extruder));
        for (const std::string& failure : stack.failures()) {
            if (failures && std::find(failures->begin(), failures->end(), failure) == failures->end())
                failures->push_back(failure);
        }
    }
    values["extruder_nr"] = std::to_string(extruder);
    return Settings(scope, std::move(values));
}

}  // namespace mixengine
