#include "planning/Motion.h"

#include <algorithm>

#include "toolpaths/core/FeatureStyle.h"

namespace mixengine {
namespace {

/// The acceleration and jerk keys of a kind of move.
struct MotionKeys {
    Key<SettingUnit::MmPerS2> acceleration;
    Key<SettingUnit::MmPerS> jerk;
};

constexpr MotionKeys kTravelKeys{key::acceleration_travel, key::jerk_travel};
constexpr MotionKeys kTravelFirstKeys{key::acceleration_travel_layer_0, key::jerk_travel_layer_0};
constexpr MotionKeys kPrintFirstKeys{key::acceleration_print_layer_0, key::jerk_print_layer_0};

/// The keys of an extrusion of `feature`: <kind>_<feature> (acceleration_wall_0, …, jerk_ironing),
/// raft_<layer>_<kind> for the raft, <kind>_print for the rest.
MotionKeys featureMotionKeys(Feature feature) {
    switch (feature) {
        case Feature::RaftBase:
            return {key::raft_base_acceleration, key::raft_base_jerk};
        case Feature::RaftInterface:
            return {key::raft_interface_acceleration, key::raft_interface_jerk};
        case Feature::RaftSurface:
            return {key::raft_surface_acceleration, key::raft_surface_jerk};
        case Feature::WallOuter:
            return {key::acceleration_wall_0, key::jerk_wall_0};
        case Feature::WallInner:
            return {key::acceleration_wall_x, key::jerk_wall_x};
        case Feature::Skin:
            return {key::acceleration_topbottom, key::jerk_topbottom};
        case Feature::Fill:
            return {key::acceleration_infill, key::jerk_infill};
        case Feature::Support:
            return {key::acceleration_support_infill, key::jerk_support_infill};
        case Feature::SupportInterface:
            return {key::acceleration_support_roof, key::jerk_support_roof};
        case Feature::SupportBottom:
            return {key::acceleration_support_bottom, key::jerk_support_bottom};
        case Feature::Skirt:
        case Feature::DraftShield:
            return {key::acceleration_skirt_brim, key::jerk_skirt_brim};
        case Feature::PrimeTower:
            return {key::acceleration_prime_tower, key::jerk_prime_tower};
        case Feature::Ironing:
            return {key::acceleration_ironing, key::jerk_ironing};
        case Feature::Roofing:
            return {key::acceleration_roofing, key::jerk_roofing};
        default:
            return {key::acceleration_print, key::jerk_print};
    }
}

/// True for the raft's features, which keep their own values on every layer.
bool isRaft(Feature feature) {
    return feature == Feature::RaftBase || feature == Feature::RaftInterface ||
           feature == Feature::RaftSurface;
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
    const MotionKeys keys = travel ? kTravelKeys : featureMotionKeys(at.feature);
    const MotionKeys first = travel ? kTravelFirstKeys : kPrintFirstKeys;
    // layers below the model (negative), skirts and the raft keep their own values, as in CuraEngine
    const bool smooth = travel || (markedFeature(at.feature) != Feature::Skirt && !isRaft(at.feature));
    if (sources.acceleration_enabled)
        step.acceleration_mm_s2 = smooth ? slowdownValue(s, keys.acceleration, first.acceleration, layer)
                                         : s.accelerationMmPerS2(keys.acceleration);
    if (sources.jerk_enabled)
        step.jerk_mm_s =
            smooth ? slowdownValue(s, keys.jerk, first.jerk, layer) : s.velocityMmPerS(keys.jerk);
}

}  // namespace

MotionSources motionSources(const Settings& global, std::vector<const Settings*> meshes,
                            const std::vector<Settings>& extruders) {
    MotionSources sources;
    sources.acceleration_enabled = global.boolean(key::acceleration_enabled);
    sources.jerk_enabled = global.boolean(key::jerk_enabled);
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
