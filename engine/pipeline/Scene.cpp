#include "pipeline/Scene.h"

#include <cstdlib>

#include "common/Error.h"
#include "mesh/BuildVolume.h"
#include "mesh/build/MeshBuilder.h"
#include "mesh/formats/ModelReader.h"
#include "orient/OrientSettings.h"
#include "settings/FrontendValues.h"
#include "settings/NotHonoured.h"
#include "settings/SettingLimits.h"
#include "settings/profiles/ProfileSelector.h"

namespace mixengine {
namespace {

void placeMesh(Mesh& mesh, const Settings& group, const Settings& settings) {
    coord_um dx = 0, dy = 0, dz = 0;
    if (!group.boolean(key::machine_center_is_zero)) {
        dx += group.lengthMicrons(key::machine_width) / 2;
        dy += group.lengthMicrons(key::machine_depth) / 2;
    }
    if (settings.boolean(key::center_object)) {
        const AABB3 box = mesh.bounds();
        dx -= (box.min.x + box.max.x) / 2;
        dy -= (box.min.y + box.max.y) / 2;
        dz -= box.min.z;
    }
    dx += settings.lengthMicrons(key::mesh_position_x);
    dy += settings.lengthMicrons(key::mesh_position_y);
    dz += settings.lengthMicrons(key::mesh_position_z);
    mesh.translate(dx, dy, dz);
}

/// Reports a placed mesh reaching outside the build volume; refuses one far larger than it.
void checkPlacement(const Mesh& mesh, const Settings& group, Log& log) {
    const BuildVolume volume =
        machineVolume(group.lengthMicrons(key::machine_width), group.lengthMicrons(key::machine_depth),
                      group.lengthMicrons(key::machine_height), group.boolean(key::machine_center_is_zero));
    const std::string warning = checkBuildVolume(mesh.name, mesh.bounds(), volume);
    if (!warning.empty())
        log.warning(warning);
}

/// The keys the user gave (-s, -e, -g, per mesh), to name them when a computed value is out of range.
std::vector<std::string> givenKeys(const SliceRequest& request) {
    std::vector<std::string> keys;
    for (const auto& [key, value] : request.user.global)
        keys.push_back(key);
    for (const auto& [nr, values] : request.user.extruders)
        for (const auto& [key, value] : values)
            keys.push_back(key);
    for (const MeshGroupInput& group : request.groups) {
        for (const auto& [key, value] : group.settings)
            keys.push_back(key);
        for (const MeshInput& mesh : group.meshes)
            for (const auto& [key, value] : mesh.settings)
                keys.push_back(key);
    }
    return keys;
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

/// `formula_failures` collects the definition formulas that fail only in a mesh's scope.
void addMeshes(const Scene& scene, const UserSettings& request_user, const MeshInput& input,
               SceneGroup& group, Log& log, std::vector<std::string>& formula_failures) {
    std::vector<TriangleSoup> loaded;
    const std::vector<TriangleSoup>& soups = soupsOf(input, loaded, log);
    std::size_t kept = 0;
    std::vector<std::string> skipped;
    for (std::size_t part = 0; part < soups.size(); ++part) {
        const std::string name = soups.size() == 1 ? input.name : input.name + "#" + soups[part].name;
        Settings settings =
            resolveMesh(scene.definitions, request_user, scene.machine, group.settings, input.settings,
                        input.default_extruder, name, &scene.profiles, &formula_failures);
        MeshBuildStats stats;
        Mesh mesh = buildMesh(soups[part], input.transform, &stats, name);
        if (stats.degenerate_dropped || stats.duplicates_dropped) {
            log.info(name + ": dropped " + std::to_string(stats.degenerate_dropped) + " degenerate and " +
                     std::to_string(stats.duplicates_dropped) + " duplicate facets");
        }
        if (mesh.faces.empty()) {
            skipped.push_back(name);
            continue;
        }
        mesh.name = name;
        group.meshes.push_back({std::move(mesh), std::move(settings)});  // placed by prepareScene
        ++kept;
    }
    if (kept == 0 && input.file)  // a model file that gives nothing to slice is an error, not a skip
        throw InputError(input.name +
                         ": no facets left after removing degenerate (zero-area) and "
                         "duplicate facets: nothing to slice");
    for (const std::string& name : skipped)
        log.warning(name + ": no facets left after cleaning; skipped");
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
    const std::vector<std::string> given = givenKeys(request);
    checkLineWidths(scene.machine.global, given);
    for (const Settings& extruder : scene.machine.extruders)
        checkLineWidths(extruder, given);
    const int trains = static_cast<int>(scene.machine.extruders.size());
    for (const std::string& warning :
         notHonouredWarnings(embeddedNotHonoured(), scene.definitions, request.user, trains))
        log.warning(warning);
    for (std::size_t g = 0; g < request.groups.size(); ++g) {
        SceneGroup& group = scene.groups[g];
        for (const MeshInput& input : request.groups[g].meshes)
            addMeshes(scene, request.user, input, group, log, scene.machine.formula_failures);
        for (const SceneMesh& m : group.meshes)
            checkLineWidths(m.settings, given);
        // Dual-nozzle orientation pass (orient/OrientSettings.h): before placement.
        std::vector<std::pair<Mesh*, int>> by_extruder;
        for (SceneMesh& m : group.meshes)
            by_extruder.emplace_back(&m.mesh, m.settings.extruderIndex(key::extruder_nr));
        orient::orientForDualNozzle(by_extruder, group.settings, scene.machine.extruders, log);
        for (SceneMesh& m : group.meshes) {
            placeMesh(m.mesh, group.settings, m.settings);
            checkPlacement(m.mesh, group.settings, log);
        }
    }
    bool any = false;
    for (const SceneGroup& group : scene.groups)
        any = any || !group.meshes.empty();
    if (!any)
        throw InputError("nothing to slice: no model given (use -l model.stl)");
    return scene;
}

}  // namespace mixengine
