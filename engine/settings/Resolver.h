#pragma once
// Settings resolution: definition values + the user's values (-s, or Cura's Slice message) →
// immutable Settings views for the global scope, each extruder train and each mesh.
//
// Order, most important first:
//   extruder train: its -eN user values > global user values > the extruder definition's values
//                   > the machine definition's values;
//   global:         global user values > the machine definition (with its inherits chain);
//   mesh:           mesh user values > its extruder train (extruder_nr of the mesh, else the
//                   extruder in focus when it was loaded) — except keys with limit_to_extruder,
//                   which are read from the target extruder's own view once (never recursively).
#include <map>
#include <vector>

#include "settings/DefinitionSet.h"
#include "settings/Settings.h"

namespace mixengine {

struct UserSettings {
    SettingValues global;
    std::map<int, SettingValues> extruders;  ///< by extruder_nr
};

struct ResolvedMachine {
    Settings global;
    std::vector<Settings> extruders;  ///< index = extruder_nr; at least one
};

ResolvedMachine resolveMachine(const DefinitionSet& definitions, const UserSettings& user);

/// A mesh group's view: the global view with the group's own values on top.
Settings resolveMeshGroup(const ResolvedMachine& machine, const SettingValues& group_user, int group_index);

/// A mesh's view. `default_extruder` is the train in focus when the mesh was given.
Settings resolveMesh(const DefinitionSet& definitions, const ResolvedMachine& machine, const Settings& group,
                     const SettingValues& mesh_user, int default_extruder, const std::string& mesh_name);

}  // namespace mixengine
