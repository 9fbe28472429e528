#include "planning/Motion.h"

#include <algorithm>
#include <map>
#include <string>

#include "toolpaths/core/FeatureStyle.h"

namespace mixengine {
namespace {

/// The acceleration (`kind` "acceleration") or jerk ("jerk") key of an extrusion of `feature`:
/// <kind>_<feature> (acceleration_wall_0, …, acceleration_ironing), raft_<layer>_<kind> for the raft.
std::string featureKey(Feature feature, const std::string& kind) {
    switch (feature) {
        case Feature::RaftBase:
            return "raft_base_" + kind;
        case Feature::RaftInterface:
            return "raft_interface_" + kind;
        case Feature::RaftSurface:
            return "raft_surface_" + kind;
        default:
            break;
    }
    static const std::map<Feature, std::string> suffix{
        {Feature::WallOuter, "wall_0"},       {Feature::WallInner, "wall_x"},
        {Feature::Skin, "topbottom"},         {Feature::Fill, "infill"},
        {Feature::Support, "support_infill"}, {Feature::SupportInterface, "support_roof"},
        {Feature::Skirt, "skirt_brim"},       {Feature::PrimeTower, "prime_tower"},
        {Feature::Ironing, "ironing"},        {Feature::DraftShield, "skirt_brim"}};
    const auto it = suffix.find(feature);
    return kind + "_" + (it != suffix.end() ? it->second : std::string("print"));
}

/// True for the raft's features, which keep their own values on every layer.
bool isRaft(Feature feature) {
    return feature == Feature::RaftBase || feature == Feature::RaftInterface ||
           feature == Feature::RaftSurface;
}

/// `key` on `layer`, blended from `first_key` over the slow-down layers (`smooth`); layers below
/// the model (negative) take `key` itself, as CuraEngine does not slow them down.
double layerValue(const Settings& s, const std::string& key, const std::string& first_key, int layer,
                  bool smooth) {
    return smooth ? slowdownValue(s, key, first_key, layer) : s.real(key);
}

struct Tracker {
    int mesh = -1;
    int extruder = 0;
    Feature feature = Feature::Fill;
};

const Settings& sourceOf(const MotionSources& sources, const Tracker& at, bool travel) {
    if (!travel && at.mesh >= 0 && static_cast<std::size_t>(at.mesh) < sources.meshes.size())
        return *sources.meshes[static_cast<std::size_t>(at.mesh)];
    const std::size_t train = std::min<std::size_t>(static_cast<std::size_t>(std::max(at.extruder, 0)),
                                                    sources.extruders->size() - 1);
    return (*sources.extruders)[train];
}

void setMotion(PlanStep& step, const MotionSources& sources, const Tracker& at, int layer) {
    const bool travel = step.kind == PlanStep::Kind::Travel;
    const Settings& s = sourceOf(sources, at, travel);
    const std::string first = travel ? "_travel_layer_0" : "_print_layer_0";
    const bool smooth = travel || (markedFeature(at.feature) != Feature::Skirt && !isRaft(at.feature));
    for (const std::string kind : {"acceleration", "jerk"}) {
        if (!(kind == "acceleration" ? sources.acceleration_enabled : sources.jerk_enabled))
            continue;
        const std::string key = travel ? kind + "_travel" : featureKey(at.feature, kind);
        const double value = layerValue(s, key, kind + first, layer, smooth);
        (kind == "acceleration" ? step.acceleration_mm_s2 : step.jerk_mm_s) = value;
    }
}

}  // namespace

MotionSources motionSources(const Settings& global, std::vector<const Settings*> meshes,
                            const std::vector<Settings>& extruders) {
    MotionSources sources;
    sources.acceleration_enabled = global.flag("acceleration_enabled");
    sources.jerk_enabled = global.flag("jerk_enabled");
    sources.meshes = std::move(meshes);
    sources.extruders = &extruders;
    return sources;
}

void assignMotion(PlannedLayer& layer, const MotionSources& sources, int extruder) {
    if ((!sources.acceleration_enabled && !sources.jerk_enabled) || sources.extruders->empty())
        return;
    Tracker at;
    at.extruder = extruder;
    for (PlanStep& step : layer.steps) {
        switch (step.kind) {
            case PlanStep::Kind::SetMesh:
                at.mesh = step.mesh_index;
                break;
            case PlanStep::Kind::SetFeature:
                at.feature = step.feature;
                break;
            case PlanStep::Kind::SetExtruder:
                at.extruder = step.extruder;
                break;
            case PlanStep::Kind::Travel:
            case PlanStep::Kind::Extrude:
                setMotion(step, sources, at, layer.index);
                break;
            default:
                break;
        }
    }
}

}  // namespace mixengine
