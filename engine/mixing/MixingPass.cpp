#include "mixing/MixingPass.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <memory>

#include "mixing/chamber/ChamberDelay.h"
#include "mixing/fields/FeatheredPaint.h"
#include "mixing/fields/FieldBands.h"
#include "mixing/fields/MixSchedule.h"
#include "mixing/fields/PaintSchedule.h"
#include "mixing/fields/RegionSplit.h"
#include "mixing/transition/LayerOrder.h"
#include "mixing/transition/MixTable.h"
#include "mixing/transition/StepContext.h"
#include "toolpaths/core/FeatureStyle.h"

namespace mixengine {
namespace {

/// One scope's schedule and the vertical extent it is measured against.
struct ScopeSchedule {
    MeshMixing mixing;
    coord_um bottom_um = 0;
    coord_um top_um = 0;
    MeshPaint paint;                    ///< color mode, painted 3MF faces: regions and their solved colours
    std::unique_ptr<FieldBands> bands;  ///< gradient along x, y or radial: its bands (the regions)
    std::unique_ptr<FeatheredPaint> feathered;  ///< painted with mixing_paint_blend: its bands (the regions)

    /// What divides the mesh into regions: its feathered paint, its paint or its bands (null: none).
    const RegionField* field() const {
        if (feathered)
            return feathered.get();
        if (paint.regions)
            return paint.regions.get();
        return bands.get();
    }
};

/// The report of one mesh's solved colours, and the warning when one is out of gamut.
void reportColors(const std::string& name, const MeshMixing& mixing, Log& log) {
    for (const SolvedColor& color : mixing.colors) {
        char de[32];
        std::snprintf(de, sizeof de, "%.2f", color.solution.delta_e00);
        log.info("mixing: '" + name + "': target " + hexOf(color.target) + " -> mix " +
                 ratioText(color.solution.mix) + ", predicted " + hexOf(color.solution.predicted_rgb) +
                 ", dE00 " + de);
        if (color.solution.delta_e00 > kGamutWarningDeltaE00)
            log.warning("mixing: '" + name + "': target colour " + hexOf(color.target) +
                        " is outside the gamut of mixing_channel_colors; printing the nearest mixable " +
                        hexOf(color.solution.predicted_rgb) + " (dE00 " + de + ")");
    }
}

const char* axisName(GradientAxis axis) {
    switch (axis) {
        case GradientAxis::X:
            return "x";
        case GradientAxis::Y:
            return "y";
        case GradientAxis::Radial:
            return "radial";
        default:
            return "z";
    }
}

/// Feathered paint's bands, when the mesh is painted with a blend (mixing_paint_blend > 0).
void featherPaint(ScopeSchedule& s, const std::string& name, double tolerance, Log& log) {
    if (!s.paint.regions || s.paint.blend_um <= 0)
        return;
    std::vector<MixVector> mixes;
    for (const SolvedColor& color : s.paint.colors)
        mixes.push_back(color.solution.mix);
    s.feathered =
        std::make_unique<FeatheredPaint>(*s.paint.regions, std::move(mixes), s.paint.blend_um, tolerance);
    char text[160];
    std::snprintf(text, sizeof text, "': painted edges feathered over %.2f mm in %d bands",
                  s.feathered->blendMm(), s.feathered->bands());
    log.info("mixing: '" + name + text);
}

std::vector<ScopeSchedule> meshSchedules(const MixingGroup& group, const MixingOutput& output,
                                         const PigmentModel* colors, double tolerance, Log& log) {
    std::vector<ScopeSchedule> schedules;
    for (const MixingMesh& m : group.meshes) {
        ScopeSchedule& s = schedules.emplace_back();
        s.mixing = parseMeshMixing(*m.settings, output, colors);
        s.bottom_um = m.bottom_um;
        s.top_um = m.top_um;
        if (s.mixing.mode == MixingMode::Color && m.mesh) {
            s.paint =
                paintOf(*m.mesh, *m.settings, parseChannelColors(*group.settings, output.channels), *colors);
            s.mixing.colors.insert(s.mixing.colors.end(), s.paint.colors.begin(), s.paint.colors.end());
            featherPaint(s, m.name, tolerance, log);
        }
        if (s.mixing.mode == MixingMode::Gradient && s.mixing.axis != GradientAxis::Z && m.mesh) {
            s.bands = std::make_unique<FieldBands>(s.mixing, *m.mesh, tolerance);
            char text[160];
            std::snprintf(text, sizeof text, "': %s gradient in %d bands of %.2f mm", axisName(s.mixing.axis),
                          s.bands->bands(), s.bands->bandWidthMm());
            log.info("mixing: '" + m.name + text);
        }
        reportColors(m.name, s.mixing, log);
    }
    return schedules;
}

/// Cuts the painted meshes' extrusions at region changes; the region of every step (−1: none).
std::vector<std::vector<int>> paintedRegions(PrintPlan& plan, const MixingGroup& group,
                                             const std::vector<ScopeSchedule>& meshes) {
    std::vector<PaintedMesh> painted;
    bool any = false;
    for (std::size_t m = 0; m < meshes.size(); ++m) {
        painted.push_back({meshes[m].field(), group.meshes[m].lift_um});
        any = any || painted.back().regions;
    }
    if (!any)
        return {};
    return splitAtRegions(plan, painted);
}

ScopeSchedule groupSchedule(const MixingGroup& group, const MixingOutput& output, const PigmentModel* colors,
                            const std::vector<ScopeSchedule>& meshes) {
    ScopeSchedule all;
    all.mixing = parseMeshMixing(*group.settings, output, colors);
    if (!meshes.empty()) {
        all.bottom_um = meshes.front().bottom_um;
        all.top_um = meshes.front().top_um;
    }
    for (const ScopeSchedule& m : meshes) {
        all.bottom_um = std::min(all.bottom_um, m.bottom_um);
        all.top_um = std::max(all.top_um, m.top_um);
    }
    return all;
}

MixVector scheduledMix(const ScopeSchedule& s, coord_um layer_z) {
    if (s.mixing.mode == MixingMode::Gradient && s.mixing.axis != GradientAxis::Z)
        return s.mixing.stops.front()
            .mix;  // outside the bands (the skirt of a print graded along x): its start
    return targetMix(s.mixing, micronsToMm(layer_z - s.bottom_um), micronsToMm(s.top_um - s.bottom_um));
}

/// The scope of the raft's extrusions in a layer's mix table (meshes are ≥ 0, non-mesh −1), and of
/// the support's and the draft shield's.
constexpr int kRaftScope = -2;
constexpr int kSupportScope = -3;

bool isRaft(Feature feature) {
    return feature == Feature::RaftBase || feature == Feature::RaftInterface ||
           feature == Feature::RaftSurface;
}

bool isSupport(Feature feature) {
    return feature == Feature::Support || feature == Feature::SupportInterface ||
           feature == Feature::SupportBottom || feature == Feature::DraftShield;
}

int scopeOf(Feature feature, int mesh) {
    if (isRaft(feature))
        return kRaftScope;
    return isSupport(feature) ? kSupportScope : mesh;
}

/// The schedules of one group: each mesh's, the non-mesh extrusions', the raft's and the
/// support's fixed mixes.
struct GroupSchedules {
    std::vector<ScopeSchedule> meshes;
    ScopeSchedule nonmesh;
    MixVector raft;
    MixVector support;

    /// A model's mixing_core_ratio (empty for other scopes and models without one).
    std::optional<MixVector> coreOf(int scope) const {
        const bool mesh = scope >= 0 && static_cast<std::size_t>(scope) < meshes.size();
        return mesh ? meshes[static_cast<std::size_t>(scope)].mixing.core : std::nullopt;
    }

    MixVector mixOf(int scope, int region, coord_um layer_z) const {
        if (scope == kRaftScope)
            return raft;
        if (scope == kSupportScope)
            return support;
        if (region >= 0) {
            const ScopeSchedule& mesh = meshes[static_cast<std::size_t>(scope)];
            if (mesh.bands)
                return mesh.bands->bandMix(region);
            if (mesh.feathered)
                return mesh.feathered->bandMix(region);
            return mesh.paint.colors[static_cast<std::size_t>(region)].solution.mix;
        }
        const bool own = scope >= 0 && static_cast<std::size_t>(scope) < meshes.size();
        return scheduledMix(own ? meshes[static_cast<std::size_t>(scope)] : nonmesh, layer_z);
    }
};

void warnAboutDialect(const MixingOutput& output, const Settings& global, Log& log) {
    if (output.dialect == MixDialectKind::RrfColon && !global.boolean(key::relative_extrusion))
        log.warning(
            "mixing_dialect rrf_colon: RepRapFirmware accepts E a:b only in relative extrusion mode; "
            "the G-code is written with relative extrusion (M83)");
}

/// Mixing is the print's choice: a model asking for a mix in a single-filament print is told so.
void warnAboutMeshModes(const MixingGroup& group, Log& log) {
    for (const MixingMesh& m : group.meshes) {
        if (m.settings->text(key::mixing_mode) != "single") {
            log.warning("mixing_mode " + m.settings->text(key::mixing_mode) +
                        " of a model is not used: mixing is off for the print (mixing_mode single); set the "
                        "print's mixing_mode to dual, gradient or color");
            return;
        }
    }
}

/// The mix each step should leave the nozzle with (index into plan.mixes) and whether it is seen:
/// an outer wall, skin or ironing of a model (not the raft's, the support's or the shield's).
std::vector<std::vector<StepTarget>> targetMixes(PrintPlan& plan, const GroupSchedules& schedules,
                                                 const std::vector<std::vector<int>>& regions) {
    MixTable table(plan.mixes);
    std::vector<std::vector<StepTarget>> targets(plan.layers.size());
    for (std::size_t l = 0; l < plan.layers.size(); ++l) {
        const PlannedLayer& layer = plan.layers[l];
        targets[l].resize(layer.steps.size());
        int mesh = -1;
        Feature feature = Feature::Fill;
        // (scope: mesh index, -1 = non-mesh, -2 = raft, -3 = support; painted region or -1) → mix index
        std::map<std::pair<int, int>, int> layer_mix;
        for (std::size_t i = 0; i < layer.steps.size(); ++i) {
            const PlanStep& step = layer.steps[i];
            if (step.kind == PlanStep::Kind::SetMesh)
                mesh = step.mesh_index;
            if (step.kind == PlanStep::Kind::SetFeature)
                feature = step.feature;
            if (step.kind != PlanStep::Kind::Extrude)
                continue;
            const int scope = scopeOf(feature, mesh);
            const int region = regions.empty() ? -1 : regions[l][i];
            StepTarget& t = targets[l][i];
            t.visible = scope >= 0 && visibleFeature(feature);
            if (step.rise_um > 0) {  // a spiral: the mix at the height the move ends at
                t.mix = table.indexOf(schedules.mixOf(scope, region, layer.z + step.rise_um));
                continue;
            }
            auto [it, added] = layer_mix.emplace(std::pair{scope, region}, 0);
            if (added)
                it->second = table.indexOf(schedules.mixOf(scope, region, layer.z));
            t.mix = it->second;
            const std::optional<MixVector> core = schedules.coreOf(scope);
            if (core && !t.visible) {  // a colour shell over a plain core (mixing_core_ratio)
                t.mix = table.indexOf(*core);
                t.core = true;
            }
        }
    }
    return targets;
}

/// Whether some layer that shows a visible extrusion asks for more than one mix: two models, painted regions,
/// or support, raft or shield in another mix than the model beside them.
bool mixChangesInLayers(const std::vector<std::vector<StepTarget>>& targets) {
    for (const std::vector<StepTarget>& layer : targets) {
        int first = -1;
        bool visible = false, several = false;
        for (const StepTarget& t : layer) {
            if (t.mix < 0)
                continue;
            visible = visible || t.visible;
            several = several || (first >= 0 && t.mix != first);
            first = t.mix;
        }
        if (visible && several)
            return true;
    }
    return false;
}

/// Without changes inside layers: every extrusion commands its target, shifted earlier by the
/// chamber's volume — the mean residence time of the chamber, which is exactly the lag of a slowly
/// changing mix through any number of stirred tanks (mixing/chamber/ChamberDelay.h).
void delayShift(PrintPlan& plan, const std::vector<std::vector<StepTarget>>& targets, double chamber_mm3) {
    std::vector<int> target;
    std::vector<double> volume;
    for (std::size_t l = 0; l < plan.layers.size(); ++l)
        for (std::size_t i = 0; i < plan.layers[l].steps.size(); ++i)
            if (plan.layers[l].steps[i].kind == PlanStep::Kind::Extrude) {
                target.push_back(targets[l][i].mix);
                volume.push_back(plan.layers[l].steps[i].volume_mm3);
            }
    const std::vector<int> commanded = delayCompensated(target, volume, chamber_mm3);
    std::size_t next = 0;
    for (PlannedLayer& layer : plan.layers)
        for (PlanStep& step : layer.steps)
            if (step.kind == PlanStep::Kind::Extrude)
                step.mix = commanded[next++];
}

TransitionSettings transitionSettings(const Settings& global, const ChamberSpec& chamber, double tolerance) {
    TransitionSettings t;
    t.chamber = chamber;
    t.tolerance = tolerance;
    t.tower = parsePurgeTower(global);
    const coord_um w = global.lengthMicrons(key::machine_width);
    const coord_um d = global.lengthMicrons(key::machine_depth);
    if (global.boolean(key::machine_center_is_zero)) {
        t.site.plate_min = {-w / 2, -d / 2};
        t.site.plate_max = {w / 2, d / 2};
    } else {
        t.site.plate_max = {w, d};
    }
    t.site.preferred_anchor = Point2{global.lengthMicrons(key::prime_tower_position_x),
                                     global.lengthMicrons(key::prime_tower_position_y)};
    for (const Key<SettingUnit::Millimetres> width :
         {key::prime_tower_line_width, key::line_width, key::machine_nozzle_size})
        if (global.lengthMicrons(width) > 0) {
            t.line_width_um = global.lengthMicrons(width);
            break;
        }
    if (global.velocityMmPerS(key::speed_prime_tower) > 0) {
        t.speed_mm_s = global.velocityMmPerS(key::speed_prime_tower);
        // as every feature: speed_print_layer_0 on the first layer, ramping up over speed_slowdown_layers
        t.speed_at = [&global](int layer) { return layerSpeed(global, key::speed_prime_tower, layer); };
    }
    return t;
}

/// Whether every change is between models that stand apart (no painted regions, disjoint in XY).
std::string sequenceHint(const MixingGroup& group, const std::vector<std::vector<int>>& regions,
                         const TransitionReport& report) {
    if (report.changes == 0 || !regions.empty() || group.meshes.size() < 2)
        return "";
    if (group.settings->text(key::print_sequence) == "one_at_a_time")
        return "";
    for (std::size_t a = 0; a < group.meshes.size(); ++a)
        for (std::size_t b = a + 1; b < group.meshes.size(); ++b) {
            if (!group.meshes[a].mesh || !group.meshes[b].mesh)
                return "";
            const auto ba = group.meshes[a].mesh->bounds(), bb = group.meshes[b].mesh->bounds();
            const bool apart =
                ba.max.x < bb.min.x || bb.max.x < ba.min.x || ba.max.y < bb.min.y || bb.max.y < ba.min.y;
            if (!apart)
                return "";
        }
    char cost[96];
    if (report.purge_mm3 > 0.5)
        std::snprintf(cost, sizeof cost, " and the %.0f mm3 of purge", report.purge_mm3);
    else
        std::snprintf(cost, sizeof cost, " (%.0f mm3 of them left unpurged)", report.unpurged_mm3);
    char text[320];
    std::snprintf(
        text, sizeof text,
        "mixing: the models stand apart: printing them one at a time (print_sequence one_at_a_time) would "
        "remove the %d changes of mix%s",
        report.changes, cost);
    return text;
}

/// Whether the chamber, as earlier groups left it, must change before this group's first visible extrusion.
bool firstChangeNeeded(const PrintPlan& plan, const std::vector<std::vector<StepTarget>>& targets,
                       const Chamber& incoming, double tolerance) {
    for (const std::vector<StepTarget>& layer : targets)
        for (const StepTarget& t : layer)
            if (t.visible && t.mix >= 0)
                return incoming.volumeToReach(plan.mixes[static_cast<std::size_t>(t.mix)], tolerance) > 0;
    return false;
}

/// One warning per model whose field (x, y or radial) the chamber cannot follow without purging.
void warnAboutFields(const MixingGroup& group, const std::vector<ScopeSchedule>& meshes,
                     const MixingReport& report, Log& log) {
    if (report.transitions.changes == 0)
        return;
    for (std::size_t m = 0; m < meshes.size(); ++m) {
        if (!meshes[m].bands || meshes[m].bands->bands() < 2)
            continue;
        const auto it = report.visible.by_mesh.find(static_cast<int>(m));
        const VisibleFigure figure = it == report.visible.by_mesh.end() ? VisibleFigure{} : it->second;
        const double whole = figure.visible_mm > 0 ? figure.visible_mm : 1.0;
        const double within = figure.within_share_mm / whole;
        if (report.transitions.purge_mm3 <= 0 && within >= 0.98)
            continue;  // the chamber follows it unaided
        char text[480];
        std::snprintf(
            text, sizeof text,
            "': its %s gradient changes faster than the mixing chamber can follow unaided (%d bands of %.1f "
            "mm "
            "in a layer, the chamber commanded ahead of the field): the print purges %.0f mm3 for it "
            "and the fields of the other models, and %.1f %% of its visible surface leaves the nozzle "
            "within %.2f of the field (%.1f %% within dE00 3 of it)%s",
            axisName(meshes[m].mixing.axis), meshes[m].bands->bands(), meshes[m].bands->bandWidthMm(),
            report.transitions.purge_mm3, 100.0 * within, report.tolerance,
            100.0 * figure.within_de_mm / whole,
            within < 0.9 ? "; more volume per layer (thicker layers, more walls or infill) lets the "
                           "chamber follow it"
                         : "");
        log.warning("mixing: '" + group.meshes[m].name + text);
    }
}

/// StepTarget::exact of every visible extrusion of a mesh whose field is continuous: the field's own mix
/// at the middle of the move, mid-layer, in the mesh's frame (as mixing/fields/RegionSplit.h looks regions
/// up).
void markExactTargets(PrintPlan& plan, const MixingGroup& group, const std::vector<ScopeSchedule>& meshes,
                      std::vector<std::vector<StepTarget>>& targets) {
    MixTable table(plan.mixes);
    for (std::size_t l = 0; l < plan.layers.size(); ++l) {
        const PlannedLayer& layer = plan.layers[l];
        const coord_um mid_layer = layer.z - (layer.thickness > 0 ? layer.thickness / 2 : 100);
        Point2 at{};
        const RegionField* field = nullptr;
        coord_um lift_um = 0;
        for (std::size_t i = 0; i < layer.steps.size(); ++i) {
            const PlanStep& step = layer.steps[i];
            if (step.kind == PlanStep::Kind::SetMesh) {
                const bool ours =
                    step.mesh_index >= 0 && static_cast<std::size_t>(step.mesh_index) < meshes.size();
                field = ours ? meshes[static_cast<std::size_t>(step.mesh_index)].field() : nullptr;
                lift_um = ours ? group.meshes[static_cast<std::size_t>(step.mesh_index)].lift_um : 0;
            }
            if (step.kind == PlanStep::Kind::Extrude && field && targets[l][i].visible && step.rise_um == 0) {
                const Point3 mid{(at.X + step.to.X) / 2, (at.Y + step.to.Y) / 2, mid_layer - lift_um};
                if (const std::optional<MixVector> exact = field->exactMixAt(mid))
                    targets[l][i].exact = table.indexOf(roundedMix(*exact));
            }
            if (movesHead(step))
                at = step.to;
        }
    }
}

}  // namespace

MixingReport assignMixes(PrintPlan& plan, const MixingGroup& group, Log& log) {
    const MixingOutput output = parseMixingOutput(*group.settings);
    if (!output.enabled()) {
        warnAboutMeshModes(group, log);
        return {};
    }
    // The channel colours' pigment model (a few milliseconds): any scope may ask for a colour.
    const PigmentModel colors(parseChannelColors(*group.settings, output.channels));
    const PigmentModel* model = &colors;
    MixingReport report;
    report.mixing = true;
    report.chamber = parseChamberSpec(*group.settings);
    report.tolerance = parseTransitionTolerance(*group.settings);
    GroupSchedules schedules;
    schedules.meshes = meshSchedules(group, output, model, report.tolerance, log);
    schedules.nonmesh = groupSchedule(group, output, model, schedules.meshes);
    schedules.raft = parseRaftMix(*group.settings, output);
    schedules.support = parseSupportMix(*group.settings, output);
    warnAboutDialect(output, *group.settings, log);

    const std::vector<std::vector<int>> regions = paintedRegions(plan, group, schedules.meshes);
    std::vector<std::vector<StepTarget>> targets = targetMixes(plan, schedules, regions);
    markExactTargets(plan, group, schedules.meshes, targets);
    std::optional<Chamber> fresh;
    std::optional<Chamber>& chamber = group.chamber ? *group.chamber : fresh;
    const std::optional<Chamber> incoming = chamber;  // what the groups printed before left in it
    const bool starts_changed = incoming && firstChangeNeeded(plan, targets, *incoming, report.tolerance);
    if (!report.chamber.ideal() && (mixChangesInLayers(targets) || starts_changed)) {
        report.planned = true;
        TransitionSettings settings = transitionSettings(*group.settings, report.chamber, report.tolerance);
        settings.threads = group.threads;
        settings.incoming = incoming;
        settings.keep_clear = group.printed_before;
        report.transitions = planTransitions(plan, targets, settings);
        report.sequence_hint = sequenceHint(group, regions, report.transitions);
        for (const std::string& warning : report.transitions.warnings)
            log.warning(warning);
    } else {
        delayShift(plan, targets, report.chamber.volume_mm3);
    }
    report.visible = predictOutlet(plan, targets, chamber, report.chamber, report.tolerance, colors);
    warnAboutFields(group, schedules.meshes, report, log);
    return report;
}

}  // namespace mixengine
