#include "planning/PrintPlanner.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>

#include "planning/Cooling.h"
#include "planning/Motion.h"
#include "planning/PathOrder.h"
#include "planning/Temperatures.h"
#include "toolpaths/PolygonOps.h"

namespace mixengine {

namespace {

void collectExtruders(const std::vector<ExtrusionPath>& paths, std::set<int>& used) {
    for (const ExtrusionPath& path : paths)
        used.insert(path.extruder);
}

std::vector<ExtrusionPath> ofExtruder(const std::vector<ExtrusionPath>& paths, int extruder) {
    std::vector<ExtrusionPath> selected;
    for (const ExtrusionPath& path : paths) {
        if (path.extruder == extruder)
            selected.push_back(path);
    }
    return selected;
}

/// CuraEngine's reach for moving travel ends into the comb area: twice its comb offset, which is
/// twice the innermost wall's width (× initial_layer_line_width_factor on layer 0).
coord_um combMoveInside(const Settings& s, int layer) {
    if (!s.has("wall_line_width_0"))
        return 0;
    const bool several = s.has("wall_line_count") && s.integer("wall_line_count") > 1;
    double width = double(s.lengthMicrons(several ? "wall_line_width_x" : "wall_line_width_0"));
    if (layer == 0 && s.has("initial_layer_line_width_factor"))
        width *= s.ratio("initial_layer_line_width_factor");
    return static_cast<coord_um>(std::llround(4 * width));
}

TravelParams travelParams(const Settings& s, int layer, coord_um thickness, const CombBoundary* comb,
                          const CombBoundary* free) {
    TravelParams p;
    if (!s.has("retraction_combing") || s.text("retraction_combing") != "off")
        p.comb = comb;
    if (!s.has("travel_avoid_other_parts") || s.boolean("travel_avoid_other_parts"))
        p.free = free;
    p.limit_support_retractions =
        s.has("limit_support_retractions") && s.boolean("limit_support_retractions");
    if (s.has("retraction_combing_max_distance"))
        p.combing_max_distance_um = s.lengthMicrons("retraction_combing_max_distance");
    p.comb_move_inside_um = combMoveInside(s, layer);
    p.travel_speed_mm_s = s.velocityMmPerS(layer == 0 ? "speed_travel_layer_0" : "speed_travel");
    p.retraction_enable = s.boolean("retraction_enable");
    p.retraction_min_travel_um = s.lengthMicrons("retraction_min_travel");
    p.layer_thickness_um = thickness;
    if (s.has("wall_0_wipe_dist") && !(s.has("magic_spiralize") && s.boolean("magic_spiralize")))
        p.wall_0_wipe_um = s.lengthMicrons("wall_0_wipe_dist");
    if (s.has("infill_wipe_dist"))
        p.infill_wipe_um = s.lengthMicrons("infill_wipe_dist");
    return p;
}

void addMeshMarker(int mesh_index, std::vector<PlanStep>& steps) {
    PlanStep marker;
    marker.kind = PlanStep::Kind::SetMesh;
    marker.mesh_index = mesh_index;
    steps.push_back(marker);
}

struct LayerContext {
    int layer = 0;
    coord_um thickness = 0;
    int extruder = 0;
    const Settings* extruder_settings = nullptr;
    const CombBoundary* comb = nullptr;
    const CombBoundary* free = nullptr;  ///< outside the parts grown by travel_avoid_distance
};

/// The order of a mesh's groups on a layer: walls (inner first, or outer first — outerWallFirst),
/// skin, infill — infill first with infill_before_walls. Walls grouped by outline (sequences,
/// optimize_wall_printing_order) are one group, so that each outline's loops print together.
std::vector<std::vector<ExtrusionPath>> groupOrder(const MeshLayerGroups& g, const Settings& s, int layer) {
    const bool outer_first = outerWallFirst(s, layer);
    const std::vector<ExtrusionPath>& first = outer_first ? g.outer_walls : g.inner_walls;
    const std::vector<ExtrusionPath>& second = outer_first ? g.inner_walls : g.outer_walls;
    const auto grouped = [](const ExtrusionPath& p) { return p.sequence != 0; };
    std::vector<std::vector<ExtrusionPath>> order;
    if (std::any_of(first.begin(), first.end(), grouped) ||
        std::any_of(second.begin(), second.end(), grouped)) {
        order.push_back(first);
        order.back().insert(order.back().end(), second.begin(), second.end());
    } else {
        order = {first, second};
    }
    order.push_back(g.skin);
    order.push_back(g.infill);
    if (s.has("infill_before_walls") && s.boolean("infill_before_walls"))
        std::rotate(order.begin(), order.end() - 1, order.end());
    return order;
}

void planMeshLayer(const MeshToolpaths& mesh, int mesh_index, const LayerContext& ctx, Point2& head,
                   PlannedLayer& planned) {
    const MeshLayerGroups& groups = mesh.layers[static_cast<std::size_t>(ctx.layer)];
    const TravelParams travel = travelParams(*mesh.settings, ctx.layer, ctx.thickness, ctx.comb, ctx.free);
    std::optional<Feature> feature;
    bool marked = false;
    for (const std::vector<ExtrusionPath>& group : groupOrder(groups, *mesh.settings, ctx.layer)) {
        std::vector<ExtrusionPath> selected = ofExtruder(group, ctx.extruder);
        if (selected.empty())
            continue;
        if (!marked)
            addMeshMarker(mesh_index, planned.steps);
        marked = true;
        appendOrderedPaths(std::move(selected), travel, head, feature, planned.steps);
    }
}

void planNonMesh(const std::vector<ExtrusionPath>& paths, const LayerContext& ctx, Point2& head,
                 PlannedLayer& planned) {
    std::vector<ExtrusionPath> selected = ofExtruder(paths, ctx.extruder);
    if (selected.empty())
        return;
    addMeshMarker(-1, planned.steps);
    std::optional<Feature> feature;
    appendOrderedPaths(std::move(selected),
                       travelParams(*ctx.extruder_settings, ctx.layer, ctx.thickness, nullptr, ctx.free),
                       head, feature, planned.steps);
}

std::size_t trainOf(int extruder, const std::vector<Settings>& extruders) {
    return std::min<std::size_t>(static_cast<std::size_t>(std::max(extruder, 0)), extruders.size() - 1);
}

/// retract_at_layer_change: the first travel of a layer retracts (not in spiralize mode).
void retractAtLayerStart(PlannedLayer& layer, const Settings& extruder) {
    if (!extruder.has("retract_at_layer_change") || !extruder.boolean("retract_at_layer_change") ||
        !extruder.boolean("retraction_enable") ||
        (extruder.has("magic_spiralize") && extruder.boolean("magic_spiralize")))
        return;
    for (PlanStep& step : layer.steps) {
        if (step.kind == PlanStep::Kind::Extrude)
            return;
        if (step.kind == PlanStep::Kind::Travel) {
            step.retract = true;
            return;
        }
    }
}

}  // namespace

std::vector<int> extruderOrder(const GroupToolpaths& toolpaths, std::size_t layer, int active) {
    std::set<int> used;
    if (layer == 0)
        collectExtruders(toolpaths.adhesion, used);
    if (layer < toolpaths.support.size())
        collectExtruders(toolpaths.support[layer], used);
    for (const MeshToolpaths& mesh : toolpaths.meshes) {
        const MeshLayerGroups& g = mesh.layers[layer];
        for (const auto* group : {&g.inner_walls, &g.outer_walls, &g.skin, &g.infill})
            collectExtruders(*group, used);
    }
    std::vector<int> order;
    if (used.erase(active))
        order.push_back(active);
    order.insert(order.end(), used.begin(), used.end());
    return order;
}

Paths partOutlines(const GroupToolpaths& toolpaths, std::size_t layer) {
    Paths area;
    const std::size_t sliced_layer = toolpaths.first_sliced_layer + layer;
    for (const MeshToolpaths& mesh : toolpaths.meshes) {
        if (mesh.sliced && sliced_layer < mesh.sliced->size()) {
            const Paths& outlines = (*mesh.sliced)[sliced_layer].outlines;
            area.insert(area.end(), outlines.begin(), outlines.end());
        }
    }
    return area;
}

Paths combArea(const GroupToolpaths& toolpaths, std::size_t layer) {
    Paths area;
    const std::size_t sliced_layer = toolpaths.first_sliced_layer + layer;
    for (const MeshToolpaths& mesh : toolpaths.meshes) {
        const Paths* part = nullptr;
        if (layer < mesh.layers.size() && mesh.layers[layer].comb_area)
            part = &*mesh.layers[layer].comb_area;
        else if (mesh.sliced && sliced_layer < mesh.sliced->size())
            part = &(*mesh.sliced)[sliced_layer].outlines;
        if (part)
            area.insert(area.end(), part->begin(), part->end());
    }
    return area;
}

Paths freeSpace(const Paths& outlines, coord_um avoid_distance_um) {
    if (outlines.empty())
        return {};
    Paths free = offsetPolygons(unionOf(outlines), avoid_distance_um);
    const ClipperLib::IntRect box = boundsOf(free);
    constexpr coord_um kMarginUm = 5'000;
    free.insert(free.begin(), Path{{box.left - kMarginUm, box.top - kMarginUm},
                                   {box.right + kMarginUm, box.top - kMarginUm},
                                   {box.right + kMarginUm, box.bottom + kMarginUm},
                                   {box.left - kMarginUm, box.bottom + kMarginUm}});
    return free;
}

PrintPlan planPrint(const GroupToolpaths& toolpaths, const Settings& global,
                    const std::vector<Settings>& extruders, PlannerState& state) {
    const std::vector<LayerZ>& heights = toolpaths.heights;
    PrintPlan plan;
    for (const MeshToolpaths& mesh : toolpaths.meshes)
        plan.mesh_names.push_back(mesh.name);
    const CoolingParams cooling = coolingParams(global);
    const Point2 print_start = state.head;
    std::set<int> used;
    std::vector<const Settings*> mesh_settings;
    for (const MeshToolpaths& mesh : toolpaths.meshes)
        mesh_settings.push_back(mesh.settings);
    const MotionSources motion = motionSources(global, std::move(mesh_settings), extruders);
    const coord_um avoid_distance_um =
        global.has("travel_avoid_distance") ? global.lengthMicrons("travel_avoid_distance") : 0;
    for (std::size_t i = 0; i < heights.size(); ++i) {
        const Point2 layer_start = state.head;
        const CombBoundary comb(combArea(toolpaths, i));
        const CombBoundary free(freeSpace(partOutlines(toolpaths, i), avoid_distance_um));
        const int layer_extruder = state.extruder;
        PlannedLayer planned;
        planned.index = static_cast<int>(i);
        planned.z = heights[i].print_z;
        PlanStep fan;
        fan.kind = PlanStep::Kind::SetFan;
        planned.steps.push_back(fan);
        for (int extruder : extruderOrder(toolpaths, i, state.extruder)) {
            used.insert(extruder);
            if (extruder != state.extruder) {
                PlanStep change;
                change.kind = PlanStep::Kind::SetExtruder;
                change.extruder = extruder;
                planned.steps.push_back(change);
                state.extruder = extruder;
            }
            const std::size_t train =
                std::min<std::size_t>(static_cast<std::size_t>(extruder), extruders.size() - 1);
            const LayerContext ctx{planned.index, heights[i].print_z - heights[i].bottom_z,
                                   extruder,      &extruders[train],
                                   &comb,         free.empty() ? nullptr : &free};
            if (i < toolpaths.prime_tower.size())
                planNonMesh(toolpaths.prime_tower[i], ctx, state.head, planned);
            if (i < toolpaths.ooze_shield.size())
                planNonMesh(toolpaths.ooze_shield[i], ctx, state.head, planned);
            if (i == 0)
                planNonMesh(toolpaths.adhesion, ctx, state.head, planned);
            if (i < toolpaths.support.size())
                planNonMesh(toolpaths.support[i], ctx, state.head, planned);
            for (std::size_t m = 0; m < toolpaths.meshes.size(); ++m)
                planMeshLayer(toolpaths.meshes[m], static_cast<int>(m), ctx, state.head, planned);
        }
        if (i > 0)
            retractAtLayerStart(planned, extruders[trainOf(layer_extruder, extruders)]);
        applyCooling(planned, layer_start, cooling);
        assignMotion(planned, motion, layer_extruder);
        plan.layers.push_back(std::move(planned));
    }
    const int only = used.size() == 1 ? *used.begin() : state.extruder;
    const std::size_t train = std::min<std::size_t>(static_cast<std::size_t>(only), extruders.size() - 1);
    planTemperatures(plan, temperatureParams(global, extruders[train]), used.size() == 1, print_start);
    return plan;
}

}  // namespace mixengine
