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

void warnAboutDialect(const MixingOutput& output, const Settings& global, Log& log) {
    if (output.dialect == MixDialectKind::RrfColon && !global.boolean("relative_extrusion"))
        log.warning(
            "mixing_dialect rrf_colon: RepRapFirmware accepts E a:b only in relative extrusion mode; "
            "the G-code is written with relative extrusion (M83)");
}

}  // namespace

void assignMixes(PrintPlan& plan, const MixingGroup& group, Log& log) {
    const MixingOutput output = parseMixingOutput(*group.settings);
    if (!output.enabled())
        return;
    const std::vector<ScopeSchedule> meshes = meshSchedules(group, output);
    const ScopeSchedule nonmesh = groupSchedule(group, output, meshes);
    const double chamber_mm3 = parseChamberVolumeMm3(*group.settings);
    warnAboutDialect(output, *group.settings, log);

    MixTable table(plan.mixes);
    std::vector<int> target;
    std::vector<double> volume;
    for (const PlannedLayer& layer : plan.layers) {
        int mesh = -1;
        std::map<int, int> layer_mix;  // scope (mesh index, -1 = non-mesh) → mix index on this layer
        for (const PlanStep& step : layer.steps) {
            if (step.kind == PlanStep::Kind::SetMesh)
                mesh = step.mesh_index;
            if (step.kind != PlanStep::Kind::Extrude)
                continue;
            auto [it, added] = layer_mix.emplace(mesh, 0);
            if (added) {
                const bool own = mesh >= 0 && static_cast<std::size_t>(mesh) < meshes.size();
                it->second = table.indexOf(
                    scheduledMix(own ? meshes[static_cast<std::size_t>(mesh)] : nonmesh, layer.z));
            }
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
