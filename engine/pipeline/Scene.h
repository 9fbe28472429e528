#pragma once
// Stage 1 of the pipeline: a SliceRequest becomes a Scene — the machine's definitions, the
// resolved settings of every scope, and the meshes loaded, cleaned and placed on the build plate.
//
// Placement follows CuraEngine: unless machine_center_is_zero, the plate origin is moved to
// (machine_width/2, machine_depth/2); center_object centres a mesh in XY with its bottom at z=0;
// mesh_position_x/y/z are added.
#include <vector>

#include "common/Log.h"
#include "mesh/Mesh.h"
#include "pipeline/SliceRequest.h"
#include "settings/DefinitionSet.h"
#include "settings/Resolver.h"

namespace mixengine {

struct SceneMesh {
    Mesh mesh;
    Settings settings;
};

struct SceneGroup {
    Settings settings;
    std::vector<SceneMesh> meshes;
};

struct Scene {
    DefinitionSet definitions;
    ProfileStack profiles;  ///< empty unless the request selected profiles
    ResolvedMachine machine;
    std::vector<SceneGroup> groups;
};

Scene prepareScene(const SliceRequest& request, Log& log);

/// Only the settings part (no meshes): used by `mixengine settings`.
Scene prepareSettings(const SliceRequest& request);

}  // namespace mixengine
