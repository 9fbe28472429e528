#include "planning/PrintPlanner.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>

#include "common/ComputedAhead.h"
#include "geometry/PolygonOps.h"
#include "planning/Coasting.h"
#include "planning/Cooling.h"
#include "planning/LayerWipes.h"
#include "planning/Motion.h"
#include "planning/PathOrder.h"
#include "planning/SwitchTemperatures.h"
#include "planning/Temperatures.h"
#include "planning/TravelAreas.h"
#include "planning/order/PartOrder.h"
#include "planning/order/SkinOrder.h"
#include "toolpaths/core/FeatureStyle.h"

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
    const bool several = s.integer(key::wall_line_count) > 1;
    double width = double(s.lengthMicrons(several ? key::wall_line_width_x : key::wall_line_width_0));
    if (layer == 0)
        width *= s.ratio(key::initial_layer_line_width_factor);
    return static_cast<coord_um>(std::llround(4 * width));
}

TravelParams travelParams(const Settings& s, int layer, coord_um thickness, const CombBoundary* comb,
                          const CombBoundary* free) {
    TravelParams p;
    if (s.text(key::retraction_combing) != "off")
        p.comb = comb;
    if (s.boolean(key::travel_avoid_other_parts))
        p.free = free;
    p.avoid_distance_um = s.lengthMicrons(key::travel_avoid_distance);
    p.limit_support_retractions = s.boolean(key::limit_support_retractions);
    p.combing_max_distance_um = s.lengthMicrons(key::retraction_combing_max_distance);
    p.comb_move_inside_um = combMoveInside(s, layer);
    p.max_travel_resolution_um = s.lengthMicrons(key::meshfix_maximum_travel_resolution);
    p.travel_speed_mm_s = slowdownValue(s, key::speed_travel, key::speed_travel_layer_0, layer);
    p.retraction_enable = s.boolean(key::retraction_enable);
    p.retraction_min_travel_um = s.lengthMicrons(key::retraction_min_travel);
    p.short_comb_min_um = s.lengthMicrons(key::machine_nozzle_tip_outer_diameter) / 2 * 2;
    p.layer_thickness_um = thickness;
    if (!s.boolean(key::magic_spiralize))
        p.wall_0_wipe_um = s.lengthMicrons(key::wall_0_wipe_dist);
    p.infill_wipe_um = s.lengthMicrons(key::infill_wipe_dist);
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
    const std::vector<LayerParts>* mesh_parts = nullptr;  ///< [mesh] its paths on the layer by part
};

/// One group of a mesh's paths on a layer, printed together.
struct OrderedGroup {
    std::vector<ExtrusionPath> paths;
    bool infill = false;  ///< ordered as infill (infillTravel)
    bool skin = false;    ///< a part's skin: skin part by skin part (planning/order/SkinOrder.h)
};

/// The order of a mesh's groups on a layer: walls (inner first, or outer first — outerWallFirst),
/// outline gaps, infill, skin — infill first with infill_before_walls — and ironing last. Walls grouped by
/// outline (sequences, optimize_wall_printing_order) are one group, so that each outline's loops print
/// together.
std::vector<OrderedGroup> groupOrder(const MeshLayerGroups& g, const Settings& s, int layer) {
    const bool outer_first = outerWallFirst(s, layer);
    const std::vector<ExtrusionPath>& first = outer_first ? g.outer_walls : g.inner_walls;
    const std::vector<ExtrusionPath>& second = outer_first ? g.inner_walls : g.outer_walls;
    const auto grouped = [](const ExtrusionPath& p) { return p.sequence != 0; };
    std::vector<OrderedGroup> order;
    if (std::any_of(first.begin(), first.end(), grouped) ||
        std::any_of(second.begin(), second.end(), grouped)) {
        order.push_back({first});
        order.back().paths.insert(order.back().paths.end(), second.begin(), second.end());
    } else {
        order = {{first}, {second}};
    }
    // As CuraEngine 4.13 prints a part (addMeshPartToGCode): the outline gaps (the skin group's
    // leading lines of no skin part that fill no perimeter gap), the infill, then the skin and the
    // perimeter gaps; the infill first of all with infill_before_walls.
    const auto outline_gaps_end = std::find_if(
        g.skin.begin(), g.skin.end(), [](const ExtrusionPath& p) { return p.skin_part != 0 || p.mergeable; });
    if (outline_gaps_end != g.skin.begin())
        order.push_back({std::vector<ExtrusionPath>(g.skin.begin(), outline_gaps_end), false, true});
    const std::size_t infill = order.size();
    order.push_back({g.infill, true});
    order.push_back({std::vector<ExtrusionPath>(outline_gaps_end, g.skin.end()), false, true});
    if (s.boolean(key::infill_before_walls))
        std::rotate(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(infill),
                    order.begin() + static_cast<std::ptrdiff_t>(infill) + 1);
    order.push_back({g.ironing});
    return order;
}

/// The infill's ordering: from its random start (infill_randomize_start_location), by comb
/// distances (infill_enable_travel_optimization).
TravelParams infillTravel(TravelParams travel, const MeshLayerGroups& groups, const Settings& s) {
    travel.order_from = groups.infill_start;
    travel.comb_aware_order = s.boolean(key::infill_enable_travel_optimization);
    return travel;
}

/// A skin stage's ordering: a fill of lines starting away from the seam is first looked for from
/// the one of its ExtrusionPath::seam_avoiding_starts nearer to the head (the first when as near).
TravelParams skinTravel(TravelParams travel, const std::vector<ExtrusionPath>& stage, const Point2& head) {
    if (stage.empty() || !stage.front().seam_avoiding_starts)
        return travel;
    const std::array<Point2, 2>& starts = *stage.front().seam_avoiding_starts;
    travel.order_from = distanceUm(starts[0], head) < distanceUm(starts[1], head) ? starts[0] : starts[1];
    return travel;
}

/// Whether CuraEngine prints the mesh as a model (SliceMeshStorage::isPrinted): its parts then go in
/// z seam order, else nearest first.
bool printedAsModel(const Settings& s) {
    return !s.boolean(key::infill_mesh) && !s.boolean(key::cutting_mesh);
}

/// What the groups of one mesh on a layer share while they are planned.
struct MeshRun {
    const MeshToolpaths& mesh;
    int mesh_index = 0;
    const LayerContext& ctx;
    TravelParams travel;
    std::optional<Feature> feature;
    bool marked = false;  ///< the mesh's marker is written
};

/// One stage of a skin part (planning/order/SkinOrder.h): its loops one by one, nearest vertex first
/// (loopsNearestFirst), anything else ordered together (skinTravel).
void planSkinStage(std::vector<ExtrusionPath> stage, MeshRun& run, Point2& head, PlannedLayer& planned) {
    if (stage.front().skin_stage != 1) {
        const TravelParams travel = skinTravel(run.travel, stage, head);
        appendOrderedPaths(std::move(stage), travel, head, run.feature, planned.steps);
        return;
    }
    for (ExtrusionPath& loop : loopsNearestFirst(std::move(stage), head))
        appendOrderedPaths({std::move(loop)}, run.travel, head, run.feature, planned.steps);
}

/// The paths of `groups` (a part's, or those in no part) for the context's extruder, in groupOrder().
void planGroups(const MeshLayerGroups& groups, MeshRun& run, Point2& head, PlannedLayer& planned) {
    const Settings& s = *run.mesh.settings;
    for (const OrderedGroup& group : groupOrder(groups, s, run.ctx.layer)) {
        std::vector<ExtrusionPath> selected = ofExtruder(group.paths, run.ctx.extruder);
        if (selected.empty())
            continue;
        if (!run.marked)
            addMeshMarker(run.mesh_index, planned.steps);
        run.marked = true;
        if (group.skin) {
            for (std::vector<ExtrusionPath>& stage : skinPrintGroups(std::move(selected), head))
                planSkinStage(std::move(stage), run, head, planned);
            continue;
        }
        appendOrderedPaths(std::move(selected),
                           group.infill ? infillTravel(run.travel, groups, s) : run.travel, head, run.feature,
                           planned.steps);
    }
}

/// Where CuraEngine's part order looks from (getLastPlannedPositionOrStartingPosition): the head once
/// the layer has a move, else the extruder's layer_start_x/_y (each layer is planned from there).
Point2 partOrderFrom(const PlannedLayer& planned, const Settings& extruder, const Point2& head) {
    for (const PlanStep& step : planned.steps) {
        if (step.kind == PlanStep::Kind::Travel || step.kind == PlanStep::Kind::Extrude)
            return head;
    }
    return {extruder.lengthMicrons(key::layer_start_x), extruder.lengthMicrons(key::layer_start_y)};
}

/// A mesh's layer part by part (planning/order/PartOrder.h), then its paths in no part and its ironing.
void planMeshLayer(const MeshToolpaths& mesh, int mesh_index, const LayerContext& ctx, Point2& head,
                   PlannedLayer& planned) {
    const MeshLayerGroups& groups = mesh.layers[static_cast<std::size_t>(ctx.layer)];
    MeshRun run{mesh,         mesh_index,
                ctx,          travelParams(*mesh.settings, ctx.layer, ctx.thickness, ctx.comb, ctx.free),
                std::nullopt, false};
    const LayerParts& parts = (*ctx.mesh_parts)[static_cast<std::size_t>(mesh_index)];
    if (printedAsModel(*mesh.settings)) {
        const Point2 from = partOrderFrom(planned, *ctx.extruder_settings, head);
        for (std::size_t part : seamPartOrder(parts, groups.seam_position, from))
            planGroups(parts.parts[part], run, head, planned);
    } else {
        std::vector<bool> done(parts.parts.size(), false);
        for (std::size_t part =
                 nearestPart(parts, done, partOrderFrom(planned, *ctx.extruder_settings, head));
             part < done.size(); part = nearestPart(parts, done, head)) {
            done[part] = true;
            planGroups(parts.parts[part], run, head, planned);
        }
    }
    planGroups(parts.rest, run, head, planned);
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

/// After the layer-change travel starting at step `first` (its travel steps in a row): when it
/// primed before its last move (onto an outer wall), a retraction in place, as CuraEngine writes
/// one at the start of the layer when the head is not retracted; its index, or −1.
int retractAfterPrimedArrival(PlannedLayer& layer, std::size_t first) {
    std::size_t end = first;
    bool primed = false;
    for (; end < layer.steps.size() && layer.steps[end].kind == PlanStep::Kind::Travel; ++end)
        primed = primed || layer.steps[end].prime_first;
    if (!primed)
        return -1;
    PlanStep in_place = layer.steps[end - 1];
    in_place.retract = true;
    in_place.prime_first = false;
    layer.steps.insert(layer.steps.begin() + static_cast<std::ptrdiff_t>(end), in_place);
    return static_cast<int>(end);
}

/// retract_at_layer_change: the first travel of a layer retracts (not in spiralize mode), and the
/// head is retracted again where that travel arrives primed (retractAfterPrimedArrival).
void retractAtLayerStart(PlannedLayer& layer, const Settings& extruder) {
    if (!extruder.boolean(key::retract_at_layer_change) || !extruder.boolean(key::retraction_enable) ||
        extruder.boolean(key::magic_spiralize))
        return;
    for (std::size_t i = 0; i < layer.steps.size(); ++i) {
        PlanStep& step = layer.steps[i];
        if (step.kind == PlanStep::Kind::Extrude)
            return;
        if (step.kind == PlanStep::Kind::Travel) {
            if (!step.retract)
                layer.layer_change_retract_step = static_cast<int>(i);
            step.retract = true;
            const int in_place = retractAfterPrimedArrival(layer, i);
            if (in_place >= 0)
                layer.layer_change_retract_step = in_place;
            return;
        }
    }
}

/// Per extruder: the last layer on which it prints a model, support or adhesion (−1: none).
std::vector<int> lastPrintLayers(const GroupToolpaths& toolpaths, std::size_t extruder_count) {
    std::vector<int> last(extruder_count, -1);
    auto note = [&](const std::vector<ExtrusionPath>& paths, std::size_t layer) {
        for (const ExtrusionPath& path : paths) {
            const auto e = static_cast<std::size_t>(std::max(path.extruder, 0));
            if (e < last.size())
                last[e] = std::max(last[e], static_cast<int>(layer));
        }
    };
    note(toolpaths.adhesion, 0);
    for (std::size_t l = 0; l < toolpaths.support.size(); ++l)
        note(toolpaths.support[l], l);
    for (const MeshToolpaths& mesh : toolpaths.meshes) {
        for (std::size_t l = 0; l < mesh.layers.size(); ++l) {
            const MeshLayerGroups& g = mesh.layers[l];
            for (const auto* group : {&g.inner_walls, &g.outer_walls, &g.skin, &g.infill})
                note(*group, l);
        }
    }
    return last;
}

void planNozzleTemperatures(PrintPlan& plan, const GroupToolpaths& toolpaths, const Settings& global,
                            const std::vector<Settings>& extruders, const std::set<int>& used,
                            int start_extruder, Point2 start) {
    const int only = used.size() == 1 ? *used.begin() : start_extruder;
    planTemperatures(plan, temperatureParams(global, extruders[trainOf(only, extruders)]), used.size() == 1,
                     start);
    if (used.size() <= 1)
        return;
    SwitchTemperatureParams params;
    params.trains = trainTemperatureParams(extruders);
    params.share_heater = global.boolean(key::machine_extruders_share_heater);
    params.last_layer = lastPrintLayers(toolpaths, extruders.size());
    planSwitchTemperatures(plan, params, start_extruder, start);
}

/// The outermost extruder of the prime tower prints its rings on every layer up to the last one on
/// which two or more extruders print, any extruder when it is switched to on the layer (as CuraEngine).
bool printsTower(const GroupToolpaths& t, const LayerContext& ctx, bool switched) {
    const auto i = static_cast<std::size_t>(ctx.layer);
    if (i >= t.prime_tower.size() || t.prime_tower[i].empty())
        return false;
    return switched ||
           (ctx.extruder == t.prime_tower_outermost && ctx.layer <= t.prime_tower_last_forced_layer);
}

/// prime_tower_wipe_enabled of the extruder switched away from: a travel to the tower's middle,
/// where the old nozzle would be (CuraEngine's post-wipe point).
void wipeOnTower(const GroupToolpaths& t, const std::vector<Settings>& extruders, int previous,
                 const LayerContext& ctx, Point2& head, PlannedLayer& planned) {
    const Settings& old = extruders[trainOf(previous, extruders)];
    if (ctx.layer == 0 || previous == ctx.extruder || !old.boolean(key::prime_tower_wipe_enabled))
        return;
    const Settings& now = *ctx.extruder_settings;
    PlanStep travel;
    travel.kind = PlanStep::Kind::Travel;
    travel.to = {t.prime_tower_middle.X - old.lengthMicrons(key::machine_nozzle_offset_x) +
                     now.lengthMicrons(key::machine_nozzle_offset_x),
                 t.prime_tower_middle.Y - old.lengthMicrons(key::machine_nozzle_offset_y) +
                     now.lengthMicrons(key::machine_nozzle_offset_y)};
    travel.speed_mm_s = travelParams(now, ctx.layer, ctx.thickness, nullptr, nullptr).travel_speed_mm_s;
    planned.steps.push_back(travel);
    head = travel.to;
}

/// What one extruder prints on a layer, in CuraEngine's order: on layer 0 the skirt or brim, the
/// ooze shield, the draft shield, its prime tower rings (and the wipe), its support, then every mesh.
void planExtruderOnLayer(const GroupToolpaths& t, const std::vector<Settings>& extruders,
                         const LayerContext& ctx, int previous, Point2& head, PlannedLayer& planned) {
    const auto i = static_cast<std::size_t>(ctx.layer);
    if (i == 0)
        planNonMesh(t.adhesion, ctx, head, planned);
    if (i < t.ooze_shield.size())
        planNonMesh(t.ooze_shield[i], ctx, head, planned);
    if (i < t.draft_shield.size())
        planNonMesh(t.draft_shield[i], ctx, head, planned);
    const bool switched = ctx.extruder != previous;
    if (printsTower(t, ctx, switched)) {
        planNonMesh(t.prime_tower[i], ctx, head, planned);
        if (switched)
            wipeOnTower(t, extruders, previous, ctx, head, planned);
    }
    if (i < t.support.size())
        planNonMesh(t.support[i], ctx, head, planned);
    for (std::size_t m = 0; m < t.meshes.size(); ++m)
        planMeshLayer(t.meshes[m], static_cast<int>(m), ctx, head, planned);
}

/// machine_extruder_end_pos_* / _start_pos_* of train `s` (_abs: a head position, so plus the
/// train's nozzle offset; else relative to `from`).
struct PositionKeys {
    Key<SettingUnit::Millimetres> x, y;
    Key<SettingUnit::Bool> absolute;
};
constexpr PositionKeys kStartPosition{key::machine_extruder_start_pos_x, key::machine_extruder_start_pos_y,
                                      key::machine_extruder_start_pos_abs};
constexpr PositionKeys kEndPosition{key::machine_extruder_end_pos_x, key::machine_extruder_end_pos_y,
                                    key::machine_extruder_end_pos_abs};

Point2 extruderPosition(const Settings& s, const PositionKeys& keys, Point2 from) {
    const Point2 pos{s.lengthMicrons(keys.x), s.lengthMicrons(keys.y)};
    if (!s.boolean(keys.absolute))
        return {from.X + pos.X, from.Y + pos.Y};
    return {pos.X + s.lengthMicrons(key::machine_nozzle_offset_x),
            pos.Y + s.lengthMicrons(key::machine_nozzle_offset_y)};
}

/// A SetExtruder step, and a Prime step when the extruder was not used before in the print. As
/// CuraEngine, the old extruder first travels to its end position and the new one starts planning
/// from its start position.
void switchTo(int extruder, const std::vector<Settings>& extruders, PlannerState& state,
              std::vector<PlanStep>& steps) {
    const Settings& old = extruders[trainOf(state.extruder, extruders)];
    PlanStep end;
    end.kind = PlanStep::Kind::Travel;
    end.to = extruderPosition(old, kEndPosition, state.head);
    end.speed_mm_s = old.velocityMmPerS(key::speed_travel);
    end.retract = old.boolean(key::retraction_enable) && end.to != state.head;
    steps.push_back(end);
    state.head = extruderPosition(extruders[trainOf(extruder, extruders)], kStartPosition, end.to);
    PlanStep change;
    change.kind = PlanStep::Kind::SetExtruder;
    change.extruder = extruder;
    steps.push_back(change);
    state.extruder = extruder;
    if (state.primed.insert(extruder).second) {
        PlanStep prime;
        prime.kind = PlanStep::Kind::Prime;
        prime.extruder = extruder;
        steps.push_back(prime);
    }
}

/// What every layer of one planPrint call shares.
struct PlanRun {
    const GroupToolpaths& toolpaths;
    const std::vector<Settings>& extruders;
    CoolingParams cooling;
    MotionSources motion;
    std::set<int> used;
    PlannerState& state;
    coord_um avoid_distance_um = 0;  ///< travel_avoid_distance
};

/// Starts `planned` with its fan step, in `steps` (empty; room made for the layer, if known).
PlannedLayer startLayer(int index, coord_um z, coord_um thickness, std::vector<PlanStep> steps = {}) {
    PlannedLayer planned;
    planned.steps = std::move(steps);
    planned.index = index;
    planned.z = z;
    planned.thickness = thickness;
    PlanStep fan;
    fan.kind = PlanStep::Kind::SetFan;
    planned.steps.push_back(fan);
    return planned;
}

/// Switches to `extruder` (switchTo() when it is not the active one).
void useExtruder(int extruder, PlannedLayer& planned, PlanRun& run) {
    run.used.insert(extruder);
    if (extruder != run.state.extruder)
        switchTo(extruder, run.extruders, run.state, planned.steps);
}

/// Retraction at the layer start (not on the print's first layer), cooling (its estimate with the
/// retractions of the extruder the layer ends with, as CuraEngine) and acceleration/jerk.
void finishLayer(PlannedLayer& planned, bool after_first, int layer_extruder, Point2 layer_start,
                 CoolingParams cooling, PlanRun& run) {
    if (after_first)
        retractAtLayerStart(planned, run.extruders[trainOf(layer_extruder, run.extruders)]);
    cooling.retract_seconds = retractSeconds(run.extruders[trainOf(run.state.extruder, run.extruders)]);
    mergeGapLines(planned, layer_extruder, [&run](int extruder) {
        const Settings& s = run.extruders[trainOf(extruder, run.extruders)];
        return GapMergeParams{s.lengthMicrons(key::machine_nozzle_size),
                              s.lengthMicrons(key::meshfix_maximum_deviation)};
    });
    applyCooling(planned, layer_start, cooling);
    assignMotion(planned, run.motion, layer_extruder);
}

/// As CuraEngine: travel on the raft combs inside its outline grown by 0.1 mm unless combing is off.
constexpr coord_um kRaftCombMarginUm = 100;

bool combsOnRaft(const Settings& global) {
    return global.text(key::retraction_combing) != "off";
}

/// A raft or filler layer: its paths, extruder by extruder (the active one first), loops before
/// lines (the raft base's outline, then its lines, as CuraEngine), without mesh markers; the
/// raft's own fan.
PlannedLayer planRaftLayer(const RaftLayer& layer, const CombBoundary& comb, bool after_first, PlanRun& run) {
    const Point2 layer_start = run.state.head;
    const int layer_extruder = run.state.extruder;
    PlannedLayer planned = startLayer(layer.index, layer.z_um, layer.thickness_um);
    std::set<int> extruders;
    collectExtruders(layer.paths, extruders);
    std::vector<int> order;
    if (extruders.erase(run.state.extruder))
        order.push_back(run.state.extruder);
    order.insert(order.end(), extruders.begin(), extruders.end());
    for (int extruder : order) {
        useExtruder(extruder, planned, run);
        const Settings& train = run.extruders[trainOf(extruder, run.extruders)];
        const TravelParams travel =
            travelParams(train, layer.index, layer.thickness_um, comb.empty() ? nullptr : &comb, nullptr);
        std::vector<ExtrusionPath> loops = ofExtruder(layer.paths, extruder), lines;
        const auto open = std::stable_partition(loops.begin(), loops.end(),
                                                [](const ExtrusionPath& path) { return path.closed; });
        lines.assign(std::make_move_iterator(open), std::make_move_iterator(loops.end()));
        loops.erase(open, loops.end());
        std::optional<Feature> feature;
        appendOrderedPaths(std::move(loops), travel, run.state.head, feature, planned.steps);
        appendOrderedPaths(std::move(lines), travel, run.state.head, feature, planned.steps);
    }
    const CoolingParams cooling =
        layer.fan_ratio >= 0 ? raftCooling(run.cooling, layer.fan_ratio) : run.cooling;
    finishLayer(planned, after_first, layer_extruder, layer_start, cooling, run);
    return planned;
}

/// About the steps model layer `i` takes: a move per point and a few per path of its meshes and
/// support (PathOrder.h reserves as much per call), so the layer's steps are allocated once.
std::size_t expectedSteps(const GroupToolpaths& toolpaths, std::size_t i) {
    std::size_t steps = 64;  // markers, fan and temperature steps
    auto add = [&](const std::vector<ExtrusionPath>& paths) {
        for (const ExtrusionPath& path : paths)
            steps += path.points.size() + 4;
    };
    for (const MeshToolpaths& mesh : toolpaths.meshes) {
        const MeshLayerGroups& groups = mesh.layers[i];
        add(groups.outer_walls);
        add(groups.inner_walls);
        add(groups.skin);
        add(groups.infill);
        add(groups.ironing);
    }
    if (i < toolpaths.support.size())
        add(toolpaths.support[i]);
    return steps;
}

/// What helper threads make ahead of planning model layer `i`: where its travel may go, each
/// mesh's paths split by part (none of it depends on where the head is), and the room for its
/// steps, allocated and written once, so that the page faults of a layer's new memory fall on the
/// helper rather than on the planner (the critical path).
struct LayerAhead {
    LayerBoundaries boundaries;
    std::vector<LayerParts> mesh_parts;  ///< [mesh] splitByPart of its layer
    std::vector<PlanStep> steps;         ///< empty, with capacity for expectedSteps()
};

LayerAhead makeAhead(const GroupToolpaths& toolpaths, std::size_t i, coord_um avoid_distance_um) {
    LayerAhead ahead{layerBoundaries(toolpaths, i, avoid_distance_um), {}, {}};
    for (const MeshToolpaths& mesh : toolpaths.meshes)
        ahead.mesh_parts.push_back(splitByPart(mesh.layers[i]));
    ahead.steps.resize(expectedSteps(toolpaths, i));  // writes every page
    ahead.steps.clear();                              // and keeps them
    return ahead;
}

/// Model layer `i`: what each extruder prints on it (planExtruderOnLayer), the active one first.
PlannedLayer planModelLayer(std::size_t i, LayerAhead ahead, bool after_first, PlanRun& run) {
    const LayerBoundaries& boundaries = ahead.boundaries;
    const GroupToolpaths& toolpaths = run.toolpaths;
    const LayerZ& height = toolpaths.heights[i];
    const Point2 layer_start = run.state.head;
    const CombBoundary& comb = boundaries.comb;
    const CombBoundary& free = boundaries.free;
    const int layer_extruder = run.state.extruder;
    PlannedLayer planned = startLayer(static_cast<int>(i), height.print_z, height.print_z - height.bottom_z,
                                      std::move(ahead.steps));
    for (int extruder : extruderOrder(toolpaths, i, run.state.extruder)) {
        useExtruder(extruder, planned, run);
        const LayerContext ctx{planned.index,
                               planned.thickness,
                               extruder,
                               &run.extruders[trainOf(extruder, run.extruders)],
                               &comb,
                               free.empty() ? nullptr : &free,
                               &ahead.mesh_parts};
        planExtruderOnLayer(toolpaths, run.extruders, ctx, layer_extruder, run.state.head, planned);
    }
    finishLayer(planned, after_first, layer_extruder, layer_start, run.cooling, run);
    return planned;
}

/// The extruders the plan will use (useExtruder): those of the raft's paths and of every model layer.
std::set<int> plannedExtruders(const GroupToolpaths& toolpaths) {
    std::set<int> used;
    for (const RaftLayer& layer : toolpaths.raft)
        collectExtruders(layer.paths, used);
    for (std::size_t i = 0; i < toolpaths.heights.size(); ++i)
        for (int extruder : extruderOrder(toolpaths, i, -1))
            used.insert(extruder);
    return used;
}

/// The temperature steps made layer by layer, when each layer's last planning step can follow
/// right after the next layer is planned: one extruder (no switch temperatures), no coasting, no
/// layer wipes; then only the temperature steps come after a layer, and they look one layer ahead.
/// Nothing when the plan must be complete first.
std::optional<TemperatureSteps> layerByLayer(const GroupToolpaths& toolpaths, const Settings& global,
                                             const std::vector<Settings>& extruders,
                                             const std::vector<CoastingParams>& coasting,
                                             const std::vector<LayerWipeParams>& wipes, Point2 print_start) {
    if (std::any_of(coasting.begin(), coasting.end(), [](const CoastingParams& c) { return c.enabled; }) ||
        std::any_of(wipes.begin(), wipes.end(), [](const LayerWipeParams& w) { return w.enabled; }))
        return std::nullopt;
    const std::set<int> used = plannedExtruders(toolpaths);
    if (used.size() != 1)
        return std::nullopt;  // as planNozzleTemperatures: several extruders (or none) plan otherwise
    return TemperatureSteps(temperatureParams(global, extruders[trainOf(*used.begin(), extruders)]), true,
                            print_start);
}

/// Hands the plan's layers to FinalLayer in order, each once it is final.
struct FinalLayers {
    PrintPlan& plan;
    const FinalLayer& on_final;
    std::optional<TemperatureSteps> temperatures;  ///< set: layer by layer (see layerByLayer)
    std::size_t delivered = 0;

    void deliver(std::size_t final_count) {
        for (; on_final && delivered < final_count; ++delivered)
            on_final(plan, delivered);
    }
    /// After a layer was appended to the plan.
    void added() {
        if (temperatures)
            deliver(temperatures->add(plan));
    }
};

}  // namespace

std::vector<int> extruderOrder(const GroupToolpaths& toolpaths, std::size_t layer, int active) {
    std::set<int> used;
    if (layer == 0)
        collectExtruders(toolpaths.adhesion, used);
    if (layer < toolpaths.support.size())
        collectExtruders(toolpaths.support[layer], used);
    if (static_cast<int>(layer) <= toolpaths.prime_tower_last_forced_layer &&
        toolpaths.prime_tower_outermost >= 0)
        used.insert(toolpaths.prime_tower_outermost);
    for (const MeshToolpaths& mesh : toolpaths.meshes) {
        const MeshLayerGroups& g = mesh.layers[layer];
        for (const auto* group : {&g.inner_walls, &g.outer_walls, &g.skin, &g.infill, &g.ironing})
            collectExtruders(*group, used);
    }
    std::vector<int> order;
    if (used.erase(active))
        order.push_back(active);
    order.insert(order.end(), used.begin(), used.end());
    return order;
}

PrintPlan planPrint(const GroupToolpaths& toolpaths, const Settings& global,
                    const std::vector<Settings>& extruders, PlannerState& state, int threads) {
    PrintPlan plan;
    planPrint(plan, toolpaths, global, extruders, state, threads, {});
    return plan;
}

void planPrint(PrintPlan& plan, const GroupToolpaths& toolpaths, const Settings& global,
               const std::vector<Settings>& extruders, PlannerState& state, int threads,
               const FinalLayer& on_final) {
    for (const MeshToolpaths& mesh : toolpaths.meshes)
        plan.mesh_names.push_back(mesh.name);
    plan.layers.reserve(toolpaths.raft.size() + toolpaths.heights.size());  // final layers stay in place
    const Point2 print_start = state.head;
    std::vector<const Settings*> mesh_settings;
    for (const MeshToolpaths& mesh : toolpaths.meshes)
        mesh_settings.push_back(mesh.settings);
    const int start_extruder = state.extruder;
    PlanRun run{toolpaths,
                extruders,
                coolingParams(global),
                motionSources(global, std::move(mesh_settings), extruders),
                {},
                state,
                global.lengthMicrons(key::travel_avoid_distance)};
    std::vector<CoastingParams> coasting;
    std::vector<LayerWipeParams> wipes;
    for (const Settings& train : extruders) {
        coasting.push_back(coastingParams(train));
        wipes.push_back(layerWipeParams(train));
    }
    FinalLayers final_layers{
        plan, on_final,
        on_final ? layerByLayer(toolpaths, global, extruders, coasting, wipes, print_start) : std::nullopt,
        0};
    if (!toolpaths.raft.empty()) {
        const Paths comb_area =
            combsOnRaft(global) ? offsetPolygons(toolpaths.raft_outline, kRaftCombMarginUm) : Paths{};
        const CombBoundary raft_comb(comb_area);
        for (const RaftLayer& layer : toolpaths.raft) {
            plan.layers.push_back(planRaftLayer(layer, raft_comb, !plan.layers.empty(), run));
            final_layers.added();
        }
    }
    // Helpers run niced (ComputedAhead.h) and faster than the planner: 64 layers ahead keeps them busy and
    // bounds what the made layers hold (each mesh's paths split by part).
    constexpr std::size_t kLayersAhead = 64;
    computeAhead<LayerAhead>(
        toolpaths.heights.size(), threads, kLayersAhead,
        [&](std::size_t i) { return makeAhead(toolpaths, i, run.avoid_distance_um); },
        [&](std::size_t i, LayerAhead ahead) {
            plan.layers.push_back(planModelLayer(i, std::move(ahead), !plan.layers.empty(), run));
            final_layers.added();
        });
    if (final_layers.temperatures) {
        final_layers.deliver(final_layers.temperatures->finish(plan));
        return;
    }
    applyCoasting(plan, coasting, start_extruder);
    planLayerWipes(plan, wipes, start_extruder);
    planNozzleTemperatures(plan, toolpaths, global, extruders, run.used, start_extruder, print_start);
    final_layers.deliver(plan.layers.size());
}

}  // namespace mixengine
