#include "mixing/MixingPass.h"

#include <algorithm>
#include <cstdio>
#include <map>

#include "mixing/ChamberDelay.h"
#include "mixing/MixSchedule.h"
#include "mixing/PaintSchedule.h"
#include "mixing/RegionSplit.h"

namespace mixengine {
namespace {

/// One scope's schedule and the vertical extent it is measured against.
struct ScopeSchedule {
    MeshMixing mixing;
    coord_um bottom_um = 0;
    coord_um top_um = 0;
    MeshPaint paint;  ///< color mode, painted 3MF faces: regions and their solved colours
};

struct MixLess {
    bool operator()(const MixVector& a, const MixVector& b) const { return a.share < b.share; }
};

/// Distinct mixes, each stored once in the plan.
class MixTable {
  public:
    explicit MixTable(std::vector<MixVector>& mixes) : mixes_(mixes) {}
    int indexOf(const MixVector& mix) {
        auto [it, added] = index_.emplace(mix, static_cast<int>(mixes_.size()));
        if (added)
            mixes_.push_back(mix);
        return it->second;
    }

  private:
    std::vector<MixVector>& mixes_;
    std::map<MixVector, int, MixLess> index_;
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

std::vector<ScopeSchedule> meshSchedules(const MixingGroup& group, const MixingOutput& output,
                                         const PigmentModel* colors, Log& log) {
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
        painted.push_back({meshes[m].paint.regions.get(), group.meshes[m].lift_um});
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
           feature == Feature::DraftShield;
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

    MixVector mixOf(int scope, int region, coord_um layer_z) const {
        if (scope == kRaftScope)
            return raft;
        if (scope == kSupportScope)
            return support;
        if (region >= 0)
            return meshes[static_cast<std::size_t>(scope)]
                .paint.colors[static_cast<std::size_t>(region)]
                .solution.mix;
        const bool own = scope >= 0 && static_cast<std::size_t>(scope) < meshes.size();
        return scheduledMix(own ? meshes[static_cast<std::size_t>(scope)] : nonmesh, layer_z);
    }
};

void warnAboutDialect(const MixingOutput& output, const Settings& global, Log& log) {
    if (output.dialect == MixDialectKind::RrfColon && !global.boolean("relative_extrusion"))
        log.warning(
            "mixing_dialect rrf_colon: RepRapFirmware accepts E a:b only in relative extrusion mode; "
            "the G-code is written with relative extrusion (M83)");
}

/// Mixing is the print's choice: a model asking for a mix in a single-filament print is told so.
void warnAboutMeshModes(const MixingGroup& group, Log& log) {
    for (const MixingMesh& m : group.meshes) {
        if (m.settings->has("mixing_mode") && m.settings->text("mixing_mode") != "single") {
            log.warning("mixing_mode " + m.settings->text("mixing_mode") +
                        " of a model is not used: mixing is off for the print (mixing_mode single); set the "
                        "print's mixing_mode to dual, gradient or color");
            return;
        }
    }
}

/// The mix each extrusion should leave the nozzle with (index into plan.mixes), and its volume.
void targetMixes(PrintPlan& plan, const GroupSchedules& schedules,
                 const std::vector<std::vector<int>>& regions, std::vector<int>& target,
                 std::vector<double>& volume) {
    MixTable table(plan.mixes);
    for (std::size_t l = 0; l < plan.layers.size(); ++l) {
        const PlannedLayer& layer = plan.layers[l];
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
            if (step.rise_um > 0) {  // a spiral: the mix at the height the move ends at
                target.push_back(table.indexOf(schedules.mixOf(scope, region, layer.z + step.rise_um)));
                volume.push_back(step.volume_mm3);
                continue;
            }
            auto [it, added] = layer_mix.emplace(std::pair{scope, region}, 0);
            if (added)
                it->second = table.indexOf(schedules.mixOf(scope, region, layer.z));
            target.push_back(it->second);
            volume.push_back(step.volume_mm3);
        }
    }
}

}  // namespace

void assignMixes(PrintPlan& plan, const MixingGroup& group, Log& log) {
    const MixingOutput output = parseMixingOutput(*group.settings);
    if (!output.enabled()) {
        warnAboutMeshModes(group, log);
        return;
    }
    // The channel colours' pigment model (a few milliseconds): any scope may ask for a colour.
    const PigmentModel colors(parseChannelColors(*group.settings, output.channels));
    const PigmentModel* model = &colors;
    GroupSchedules schedules;
    schedules.meshes = meshSchedules(group, output, model, log);
    schedules.nonmesh = groupSchedule(group, output, model, schedules.meshes);
    schedules.raft = parseRaftMix(*group.settings, output);
    schedules.support = parseSupportMix(*group.settings, output);
    const double chamber_mm3 = parseChamberVolumeMm3(*group.settings);
    warnAboutDialect(output, *group.settings, log);

    const std::vector<std::vector<int>> regions = paintedRegions(plan, group, schedules.meshes);
    std::vector<int> target;
    std::vector<double> volume;
    targetMixes(plan, schedules, regions, target, volume);
    const std::vector<int> commanded = delayCompensated(target, volume, chamber_mm3);
    std::size_t next = 0;
    for (PlannedLayer& layer : plan.layers) {
        for (PlanStep& step : layer.steps) {
            if (step.kind == PlanStep::Kind::Extrude)
                step.mix = commanded[next++];
        }
    }
}

}  // namespace mixengine
