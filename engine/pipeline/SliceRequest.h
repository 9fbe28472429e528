#pragma once
// What a slice is asked for, whichever way it arrives (command line or Cura's socket): plain data
// handed to the pipeline (pipeline/Scene.h reads it), so the front ends in communication/ reach it
// downwards. Setting values are text, as the user or Cura gave them.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "mesh/build/MeshBuilder.h"
#include "mesh/formats/ModelReader.h"
#include "settings/Resolver.h"
#include "settings/profiles/ProfileSelection.h"

namespace mixengine {

struct MeshInput {
    std::string name;                           ///< ;MESH: name (CLI: the -l path)
    std::optional<std::filesystem::path> file;  ///< CLI: load from here
    std::vector<TriangleSoup> soups;            ///< socket: Cura's triangle soup (mm, Cura frame converted)
    Matrix3 transform;                          ///< mesh_rotation_matrix in force when it was given
    SettingValues settings;                     ///< per-object user values
    int default_extruder = 0;                   ///< the extruder train in focus when it was given
};

struct MeshGroupInput {
    SettingValues settings;  ///< -g values
    std::vector<MeshInput> meshes;
};

struct SliceRequest {
    std::string definition = "fdmprinter";  ///< -j: a path or a definition id
    UserSettings user;                      ///< global and -eN values
    ProfileSelection profiles;              ///< --variant/--material/--quality/--intent
    std::vector<MeshGroupInput> groups;     ///< --next starts a new group (one-at-a-time printing)
    std::filesystem::path output;           ///< -o; empty = standard output
    int threads = 0;                        ///< -m; 0 = all cores
    int verbosity = 0;                      ///< -v count
    bool progress = false;                  ///< -p
    /// True when the values come from Cura's frontend (the socket), which has already added the
    /// frontend's values (settings/FrontendValues.h); the command line adds them itself.
    bool settings_from_frontend = false;
};

}  // namespace mixengine
