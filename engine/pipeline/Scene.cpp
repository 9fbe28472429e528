#include "pipeline/Scene.h"

#include <cstdlib>

#include "common/Error.h"
#include "mesh/MeshBuilder.h"
#include "mesh/ModelReader.h"
#include "orient/OrientSettings.h"
#include "settings/FrontendValues.h"
#include "settings/profiles/ProfileSelector.h"

namespace mixengine {
namespace {

void placeMesh(Mesh& mesh, const Settings& group, const Settings& settings) {
    coord_um dx = 0, dy = 0, dz = 0;
    if (!group.boolean("machine_center_is_zero")) {
        dx += group.lengthMicrons("machine_width") / 2;
        dy += group.lengthMicrons("machine_depth") / 2;
    }
    if (settings.has("center_object") && settings.boolean("center_object")) {
        const AABB3 box = mesh.bounds();
        dx -= (box.min.x + box.max.x) / 2;
        dy -= (box.min.y + box.max.y) / 2;
        dz -= box.min.z;
    }
    if (settings.has("mesh_position_x"))
        dx += settings.lengthMicrons("mesh_position_x");
    if (settings.has("mesh_position_y"))
        dy += settings.lengthMicrons("mesh_position_y");
    if (settings.has("mesh_position_z"))
        dz += settings.lengthMicrons("mesh_position_z");
    mesh.translate(dx, dy, dz);
}

/// The input's triangles: read from its file into `loaded`, or Cura's soups as they are (no copy).
const std::vector<TriangleSoup>& soupsOf(const MeshInput& input, std::vector<TriangleSoup>& loaded,
                                         Log& log) {
    if (!input.file)
        return input.soups;
    std::vector<std::string> warnings;
    loaded = readModelFile(*input.file, warnings);
    for (const std::string& warning : warnings)
        log.warning(warning);
    return loaded;
}

void addMeshes(const Scene& scene, const UserSettings& request_user, const MeshInput& input,
               SceneGroup& group, Log& log) {
    std::vector<TriangleSoup> loaded;
    const std::vector<TriangleSoup>& soups = soupsOf(input, loaded, log);
    for (std::size_t part = 0; part < soups.size(); ++part) {
        const std::string name = soups.size() == 1 ? input.name : input.name + "#" + soups[part].name;
        Settings settings = resolveMesh(scene.definitions, request_user, scene.machine, group.settings,
                                        input.settings, input.default_extruder, name, &scene.profiles);
        MeshBuildStats stats;
        Mesh mesh = buildMesh(soups[part], input.transform, &stats);
        if (stats.degenerate_dropped || stats.duplicates_dropped) {
            log.info(name + ": dropped " + std::to_string(stats.degenerate_dropped) + " degenerate and " +
                     std::to_string(stats.duplicates_dropped) + " duplicate facets");
        }
        if (mesh.faces.empty()) {
            log.warning(name + ": no facets left after cleaning; skipped");
            continue;
        }
        mesh.name = name;
        group.meshes.push_back({std::move(mesh), std::move(settings)});  // placed by prepareScene
    }
}

}  // namespace

Scene prepareSettings(const SliceRequest& request) {
    Scene scene;
    const std::vector<std::filesystem::path> search =
        defaultSearchPath(std::getenv("CURA_ENGINE_SEARCH_PATH"));
    scene.definitions = loadDefinitionSet(request.definition, search);
    // --- profile selection (settings/profiles/ProfileSelector.h) ---
    if (request.profiles.enabled)
        scene.profiles = selectProfiles(scene.definitions, request.profiles, search);
    // --- end of profile selection ---
    scene.machine = resolveMachine(scene.definitions, request.user, &scene.profiles);
    if (!request.settings_from_frontend)
        applyFrontendValues(scene.machine, request.user);
    for (std::size_t g = 0; g < request.groups.size(); ++g) {
        SceneGroup group;
        group.settings = resolveMeshGroup(scene.machine, request.groups[g].settings, static_cast<int>(g));
        scene.groups.push_back(std::move(group));
    }
    return scene;
}

Scene prepareScene(const SliceRequest& request, Log& log) {
    Scene scene = prepareSettings(request);
    for (std::size_t g = 0; g < request.groups.size(); ++g) {
        SceneGroup& group = scene.groups[g];
        for (const MeshInput& input : request.groups[g].meshes)
            addMeshes(scene, request.user, input, group, log);
        // Dual-nozzle orientation pass (orient/OrientSettings.h): before placement.
        std::vector<std::pair<Mesh*, int>> by_extruder;
        for (SceneMesh& m : group.meshes)
            by_extruder.emplace_back(
                &m.mesh, m.settings.has("extruder_nr") ? m.settings.extruderIndex("extruder_nr") : 0);
        orient::orientForDualNozzle(by_extruder, group.settings, scene.machine.extruders, log);
        for (SceneMesh& m : group.meshes)
            placeMesh(m.mesh, group.settings, m.settings);
    }
    bool any = false;
    for (const SceneGroup& group : scene.groups)
        any = any || !group.meshes.empty();
    if (!any)
        throw InputError("nothing to slice: no model given (use -l model.stl)");
    return scene;
}

}  // namespace mixengine
