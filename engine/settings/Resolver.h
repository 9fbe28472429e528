#pragma once
// Settings resolution: definition values and formulas + the user's values (-s, or Cura's Slice
// message) → immutable Settings views for the global scope, each extruder train and each mesh.
// The order of lookup is documented in settings/StackEvaluator.h.
#include <map>
#include <vector>

#include "settings/DefinitionSet.h"
#include "settings/ProfileStack.h"
#include "settings/Settings.h"

namespace mixengine {

struct UserSettings {
    SettingValues global;
    std::map<int, SettingValues> extruders;  ///< by extruder_nr
};

struct ResolvedMachine {
    Settings global;
    std::vector<Settings> extruders;            ///< index = extruder_nr; at least one
    std::vector<std::string> formula_failures;  ///< definition formulas that fell back to default_value
};

/// Evaluates every setting of the global scope and of each extruder train (settings/StackEvaluator.h).
ResolvedMachine resolveMachine(const DefinitionSet& definitions, const UserSettings& user,
                               const ProfileStack* profiles = nullptr);

/// A mesh group's view: the global view with the group's own values on top.
Settings resolveMeshGroup(const ResolvedMachine& machine, const SettingValues& group_user, int group_index);

/// A mesh's view. `default_extruder` is the train in focus when the mesh was given; the mesh's own
/// extruder_nr, if set, wins. Formulas are re-evaluated in the mesh's scope when it has values of
/// its own. Throws InputError when the extruder does not exist. Definition formulas that fail only
/// in the mesh's scope fall back to default_value and are appended to `failures` (when given) unless
/// already there, so that each is reported once.
Settings resolveMesh(const DefinitionSet& definitions, const UserSettings& user,
                     const ResolvedMachine& machine, const Settings& group, const SettingValues& mesh_user,
                     int default_extruder, const std::string& mesh_name,
                     const ProfileStack* profiles = nullptr, std::vector<std::string>* failures = nullptr);

}  // namespace mixengine
