#include "toolpaths/GroupToolpaths.h"

#include <algorithm>
#include <set>

#include "common/ParallelFor.h"
#include "geometry/PolygonOps.h"
#include "toolpaths/EmptyLayers.h"
#include "toolpaths/InfillMeshes.h"
#include "toolpaths/OverhangingWalls.h"
#include "toolpaths/SupportedSkinFan.h"
#include "toolpaths/adhesion/Adhesion.h"
#include "toolpaths/adhesion/DraftShield.h"
#include "toolpaths/adhesion/ExtruderSkirts.h"
#include "toolpaths/adhesion/PrimeTower.h"
#include "toolpaths/support/Support.h"

namespace mixengine {
namespace {

std::vector<Paths> unitedModel(const ToolpathInput& input, int threads) {
    std::vector<Paths> model(input.heights.size());
    parallelFor(model.size(), threads, [&](std::size_t i) {
        Paths all;
        for (const ToolpathMeshInput& mesh : input.meshes) {
            if (mesh.role.printsAlone() && i < mesh.layers->size())
                all.insert(all.end(), (*mesh.layers)[i].outlines.begin(), (*mesh.layers)[i].outlines.end());
        }
        model[i] = input.meshes.size() > 1 ? unionOf(all) : std::move(all);
    });
    return model;
}

/// Whether any layer of the mesh has a print outline of its own (MeshLayerGroups::print_outline).
bool hasPrintOutlines(const MeshToolpaths& mesh) {
    return std::any_of(mesh.layers.begin(), mesh.layers.end(),
                       [](const MeshLayerGroups& layer) { return layer.print_outline.has_value(); });
}

/// The mesh's outlines on layer i as its support sees them: the print outline where the layer has
/// one, else the sliced outlines.
const Paths& supportOutline(const MeshToolpaths& toolpaths, const std::vector<SlicedLayer>& sliced,
                            std::size_t i) {
    if (i < toolpaths.layers.size() && toolpaths.layers[i].print_outline)
        return *toolpaths.layers[i].print_outline;
    return sliced[i].outlines;
}

/// The model as its support sees it, as CuraEngine 4.13 (its storage's layer outlines): unitedModel
/// with each mesh's print outlines.
std::vector<Paths> supportModel(const ToolpathInput& input, const std::vector<MeshToolpaths>& meshes,
                                int threads) {
    std::vector<Paths> model(input.heights.size());
    parallelFor(model.size(), threads, [&](std::size_t i) {
        Paths all;
        for (std::size_t m = 0; m < input.meshes.size(); ++m) {
            const ToolpathMeshInput& mesh = input.meshes[m];
            if (!mesh.role.printsAlone() || i >= mesh.layers->size())
                continue;
            const Paths& outline = supportOutline(meshes[m], *mesh.layers, i);
            all.insert(all.end(), outline.begin(), outline.end());
        }
        model[i] = input.meshes.size() > 1 ? unionOf(all) : std::move(all);
    });
    return model;
}

/// Per mesh its sliced layers with the print outlines as outlines (for its overhangs); empty for a
/// mesh without print outlines.
std::vector<std::vector<SlicedLayer>> printOutlineLayers(const ToolpathInput& input,
                                                         const std::vector<MeshToolpaths>& meshes) {
    std::vector<std::vector<SlicedLayer>> out(input.meshes.size());
    for (std::size_t m = 0; m < input.meshes.size(); ++m) {
        if (!input.meshes[m].role.printsAlone() || !hasPrintOutlines(meshes[m]))
            continue;
        out[m] = *input.meshes[m].layers;
        for (std::size_t i = 0; i < out[m].size(); ++i)
            out[m][i].outlines = supportOutline(meshes[m], *input.meshes[m].layers, i);
    }
    return out;
}

void collect(const std::vector<ExtrusionPath>& paths, std::set<int>& used) {
    for (const ExtrusionPath& path : paths)
        used.insert(path.extruder);
}

std::vector<std::set<int>> extrudersPerLayer(const GroupToolpaths& result, std::size_t layers) {
    std::vector<std::set<int>> used(layers);
    for (std::size_t i = 0; i < layers; ++i) {
        for (const MeshToolpaths& mesh : result.meshes) {
            if (i >= mesh.layers.size())
                continue;
            const MeshLayerGroups& g = mesh.layers[i];
            for (const auto* group : {&g.inner_walls, &g.outer_walls, &g.skin, &g.infill, &g.ironing})
                collect(*group, used[i]);
        }
        collect(result.support[i], used[i]);
    }
    return used;
}

Paths pointsOf(const std::vector<ExtrusionPath>& paths) {
    Paths points;
    for (const ExtrusionPath& path : paths)
        points.push_back(path.points);
    return points;
}

/// The raft's filler layers, each printing `support` (toolpaths/adhesion/RaftLayout.h).
std::vector<RaftLayer> fillerLayers(const RaftLayout& layout, const std::vector<ExtrusionPath>& support) {
    std::vector<RaftLayer> layers;
    if (support.empty())
        return layers;
    const int count = layout.fillerLayerCount();
    const coord_um height = layout.fillerLayerHeightUm();
    for (int index = -count; index < 0; ++index) {
        RaftLayer layer;
        layer.index = index;
        layer.thickness_um = height;
        layer.z_um = layout.totalThicknessUm() + coord_um(count + index + 1) * height;
        layer.paths = support;
        layers.push_back(std::move(layer));
    }
    return layers;
}

/// Everything on the first printed layer: the models, the support area and the prime tower.
Paths firstLayerArea(const GroupToolpaths& result, const std::vector<Paths>& model, const Paths& support_area,
                     const ToolpathInput& input) {
    Paths area = result.first_sliced_layer < model.size() ? model[result.first_sliced_layer] : Paths{};
    area.insert(area.end(), support_area.begin(), support_area.end());
    if (!result.prime_tower.empty() && !result.prime_tower[0].empty())
        area.push_back(primeTowerOutline(*input.global, input.extruders));
    return area;
}

/// The raft under the first printed layer and its filler layers; the model's heights lifted.
void addRaft(const ToolpathInput& input, const RaftLayout& layout, const Paths& first_layer,
             const std::vector<ExtrusionPath>& filler, GroupToolpaths& result) {
    RaftToolpaths raft = generateRaft({input.global, input.extruders, first_layer});
    if (raft.layers.empty())
        return;
    result.raft = std::move(raft.layers);
    result.raft_outline = std::move(raft.outline);
    for (RaftLayer& layer : fillerLayers(layout, filler))
        result.raft.push_back(std::move(layer));
    for (std::size_t i = 0; i < result.heights.size(); ++i) {
        const coord_um lift = layout.modelLiftUm(static_cast<int>(i));
        result.heights[i].print_z += lift;
        result.heights[i].bottom_z += lift;
    }
}

/// The skirt or brim lines of the extruders other than the adhesion extruder
/// (toolpaths/adhesion/ExtruderSkirts.h), around the tower's own brim when it has one (CuraEngine makes that
/// first), else around the adhesion.
void addOtherExtruderSkirts(const ToolpathInput& input, const std::vector<std::set<int>>& per_layer,
                            const std::vector<ExtrusionPath>& tower_brim,
                            std::vector<ExtrusionPath>& adhesion) {
    if (adhesion.empty())
        return;
    std::set<int> used{adhesion.front().extruder};
    for (const std::set<int>& layer : per_layer)
        used.insert(layer.begin(), layer.end());
    const std::vector<ExtrusionPath>& around = tower_brim.empty() ? adhesion : tower_brim;
    const std::vector<ExtrusionPath> others =
        otherExtruderSkirts(*input.global, input.extruders, areaInsideOutermost(around),
                            around.front().width_um, around.front().extruder, used);
    adhesion.insert(adhesion.end(), others.begin(), others.end());
}

/// The shields' outlines on the first printed layer, which the skirt goes around.
Paths shieldsOnFirstLayer(const GroupToolpaths& result, const Paths& draft_outline, std::size_t first) {
    Paths shields = draft_outline;
    if (first < result.ooze_shield.size()) {
        for (const ExtrusionPath& path : result.ooze_shield[first])
            shields.push_back(path.points);
    }
    return shields;
}

/// Drops the empty layers at the bottom (toolpaths/EmptyLayers.h) and says so in the notes.
void dropEmptyBottomLayers(const ToolpathInput& input, GroupToolpaths& result) {
    const std::size_t empty = leadingEmptyLayers(result, input);
    if (empty == 0)
        return;
    result.notes.push_back("removing " + std::to_string(empty) +
                           " empty layer(s) at the bottom of the print");
    dropLeadingLayers(empty, result);
}

}  // namespace

GroupToolpaths generateGroupToolpaths(const ToolpathInput& input, int threads) {
    GroupToolpaths result;
    result.heights = input.heights;
    result.meshes = generateModelToolpaths(input, threads);
    const std::vector<Paths> model = unitedModel(input, threads);

    const RaftLayout raft = raftLayout(*input.global, input.extruders);
    const std::vector<Paths> support_model = supportModel(input, result.meshes, threads);
    const std::vector<std::vector<SlicedLayer>> print_outlines = printOutlineLayers(input, result.meshes);
    SupportInput support{input.global, input.extruders, &input.heights, {}, &support_model, raft.enabled, {}};
    if (!raft.enabled && !model.empty())
        support.first_layer_exclusion = brimCoveredArea(*input.global, input.extruders, model[0]);
    for (std::size_t m = 0; m < input.meshes.size(); ++m) {
        const ToolpathMeshInput& mesh = input.meshes[m];
        support.meshes.push_back({mesh.settings, mesh.layers, mesh.role,
                                  print_outlines[m].empty() ? nullptr : &print_outlines[m]});
    }
    SupportResult support_result = generateSupport(support, threads);
    result.support = std::move(support_result.paths);
    for (MeshToolpaths& mesh : result.meshes) {
        if (mesh.settings != nullptr)
            markSupportedSkinFan(*input.global, *mesh.settings, support_result.areas, mesh.layers, threads);
    }
    markOverhangingWallsOfGroup(*input.global, input.heights, support_result.areas, result.meshes, threads);

    std::vector<std::set<int>> used = extrudersPerLayer(result, input.heights.size());
    const TowerInput tower{input.global, input.extruders, &input.heights, used, &model};
    PrimeTowerResult prime_tower = generatePrimeTower(tower);
    result.prime_tower = std::move(prime_tower.layers);
    result.prime_tower_outermost = prime_tower.outermost;
    result.prime_tower_last_forced_layer = prime_tower.last_forced_layer;
    result.prime_tower_middle = prime_tower.middle;
    result.ooze_shield = generateOozeShield(tower);
    const std::size_t first_printed =
        model.empty() ? 0 : std::min(leadingEmptyLayers(result, input), model.size() - 1);
    DraftShieldResult draft =
        generateDraftShield({input.global, input.extruders, &model, &result.support, &used, first_printed});
    result.draft_shield = std::move(draft.layers);

    if (!model.empty() && !raft.enabled) {
        // As CuraEngine, the brim goes around the support on layer 0 too, and around the prime tower
        // unless the tower has a brim of its own; around the first layer that prints when the bottom
        // ones are empty (they are dropped below).
        const std::size_t first = first_printed;
        AdhesionInput adhesion{input.global, input.extruders,
                               first == 0 ? unionOf(model[0], support_result.first_layer_area) : model[first],
                               pointsOf(result.support[first]),
                               shieldsOnFirstLayer(result, draft.outline, first)};
        const Paths tower_points = pointsOf(result.prime_tower[first]);
        adhesion.extras.insert(adhesion.extras.end(), tower_points.begin(), tower_points.end());
        if (prime_tower.outermost >= 0 && prime_tower.brim.empty())
            adhesion.models.push_back(primeTowerOutline(*input.global, input.extruders));
        AdhesionResult skirt = generateAdhesion(adhesion);
        result.adhesion = std::move(skirt.paths);
        // As CuraEngine: the support brim after the skirt or brim (toolpaths/support/Support.h).
        result.adhesion.insert(result.adhesion.end(), support_result.brim.begin(), support_result.brim.end());
        result.adhesion.insert(result.adhesion.end(), prime_tower.brim.begin(), prime_tower.brim.end());
        result.warnings = std::move(skirt.warnings);
        addOtherExtruderSkirts(input, used, prime_tower.brim, result.adhesion);
        simplifyAdhesion(*input.global, input.extruders, result.adhesion);
    }
    dropEmptyBottomLayers(input, result);
    if (raft.enabled && !result.heights.empty())
        addRaft(input, raft, firstLayerArea(result, model, support_result.first_layer_area, input),
                support_result.filler, result);
    return result;
}

}  // namespace mixengine
