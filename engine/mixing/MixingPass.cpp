#include "mixing/MixingPass.h"

#include <algorithm>
#include <map>

#include "mixing/ChamberDelay.h"
#include "mixing/MixSchedule.h"

namespace mixengine {
namespace {

/// One scope's schedule and the vertical extent it is measured against.
struct ScopeSchedule {
    MeshMixing mixing;
    coord_um bottom_um = 0;
    coord_um top_um = 0;
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

std::vector<ScopeSchedule> meshSchedules(const MixingGroup& group, const MixingOutput& output) {
    std::vector<ScopeSchedule> schedules;
    for (const MixingMesh& m : group.meshes)
        schedules.push_back({parseMeshMixing(*m.settings, output), m.bottom_um, m.top_um});
    return schedules;
}

ScopeSchedule groupSchedule(const MixingGroup& group, const MixingOutput& output,
                            const std::vector<ScopeSchedule>& meshes) {
    ScopeSchedule all{parseMeshMixing(*group.settings, output), 0, 0};
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

    MixVector mixOf(int scope, coord_um layer_z) const {
        if (scope == kRaftScope)
            return raft;
        if (scope == kSupportScope)
            return support;
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
                        "print's mixing_mode to dual or gradient");
            return;
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
    GroupSchedules schedules;
    schedules.meshes = meshSchedules(group, output);
    schedules.nonmesh = groupSchedule(group, output, schedules.meshes);
    schedules.raft = parseRaftMix(*group.settings, output);
    schedules.support = parseSupportMix(*group.settings, output);
    const double chamber_mm3 = parseChamberVolumeMm3(*group.settings);
    warnAboutDialect(output, *group.settings, log);

    MixTable table(plan.mixes);
    std::vector<int> target;
    std::vector<double> volume;
    for (const PlannedLayer& layer : plan.layers) {
        int mesh = -1;
        Feature feature = Feature::Fill;
        std::map<int, int>
            layer_mix;  // scope (mesh index, -1 = non-mesh, -2 = raft, -3 = support) → mix index
        for (const PlanStep& step : layer.steps) {
            if (step.kind == PlanStep::Kind::SetMesh)
                mesh = step.mesh_index;
            if (step.kind == PlanStep::Kind::SetFeature)
                feature = step.feature;
            if (step.kind != PlanStep::Kind::Extrude)
                continue;
            const int scope = scopeOf(feature, mesh);
            if (step.rise_um > 0) {  // a spiral: the mix at the height the move ends at
                target.push_back(table.indexOf(schedules.mixOf(scope, layer.z + step.rise_um)));
                volume.push_back(step.volume_mm3);
                continue;
            }
            auto [it, added] = layer_mix.emplace(scope, 0);
            if (added)
                it->second = table.indexOf(schedules.mixOf(scope, layer.z));
            target.push_back(it->second);
            volume.push_back(step.volume_mm3);
        }
    }
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
