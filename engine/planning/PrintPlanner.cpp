#include "planning/PrintPlanner.h"

#include <optional>

#include "planning/PathOrder.h"

namespace mixengine {

double fanRatioForLayer(const Settings& s, int layer) {
    if (!s.boolean("cool_fan_enabled"))
        return 0;
    const double first = s.ratio("cool_fan_speed_0");
    const double regular = s.ratio("cool_fan_speed_min");
    const int full = static_cast<int>(s.integer("cool_fan_full_layer")) - 1;  // 0-based layer at full speed
    if (layer >= full)
        return regular;
    return first + (regular - first) * static_cast<double>(layer) / static_cast<double>(full);
}

namespace {

TravelParams travelParams(const Settings& s, int layer, coord_um thickness) {
    TravelParams p;
    p.travel_speed_mm_s = s.velocityMmPerS(layer == 0 ? "speed_travel_layer_0" : "speed_travel");
    p.retraction_enable = s.boolean("retraction_enable");
    p.retraction_min_travel_um = s.lengthMicrons("retraction_min_travel");
    p.layer_thickness_um = thickness;
    return p;
}

void planMeshLayer(const MeshToolpathsInput& mesh, int mesh_index, int layer, coord_um thickness,
                   Point2& head, PlannedLayer& planned) {
    const MeshLayerGroups& groups = mesh.layers[static_cast<std::size_t>(layer)];
    if (groups.inner_walls.empty() && groups.outer_walls.empty() && groups.skin.empty() &&
        groups.infill.empty())
        return;
    PlanStep marker;
    marker.kind = PlanStep::Kind::SetMesh;
    marker.mesh_index = mesh_index;
    planned.steps.push_back(marker);
    const TravelParams travel = travelParams(*mesh.settings, layer, thickness);
    std::optional<Feature> feature;
    for (const auto* group : {&groups.inner_walls, &groups.outer_walls, &groups.skin, &groups.infill}) {
        appendOrderedPaths(*group, travel, head, feature, planned.steps);
    }
}

}  // namespace

PrintPlan planPrint(const std::vector<LayerZ>& heights, const std::vector<MeshToolpathsInput>& meshes,
                    const Settings& global) {
    PrintPlan plan;
    for (const MeshToolpathsInput& mesh : meshes)
        plan.mesh_names.push_back(mesh.name);
    Point2 head{0, 0};
    for (std::size_t i = 0; i < heights.size(); ++i) {
        PlannedLayer planned;
        planned.index = static_cast<int>(i);
        planned.z = heights[i].print_z;
        PlanStep fan;
        fan.kind = PlanStep::Kind::SetFan;
        fan.fan_ratio = fanRatioForLayer(global, planned.index);
        planned.steps.push_back(fan);
        const coord_um thickness = heights[i].print_z - heights[i].bottom_z;
        for (std::size_t m = 0; m < meshes.size(); ++m) {
            planMeshLayer(meshes[m], static_cast<int>(m), planned.index, thickness, head, planned);
        }
        plan.layers.push_back(std::move(planned));
    }
    return plan;
}

}  // namespace mixengine
