#include "planning/Motion.h"

#include <algorithm>
#include <string>

namespace mixengine {
namespace {

/// The key suffix of a feature: acceleration_<suffix>, jerk_<suffix>.
const char* featureSuffix(Feature feature) {
    switch (feature) {
        case Feature::WallOuter:
            return "wall_0";
        case Feature::WallInner:
            return "wall_x";
        case Feature::Skin:
            return "topbottom";
        case Feature::Fill:
            return "infill";
        case Feature::Support:
            return "support_infill";
        case Feature::SupportInterface:
            return "support_roof";
        case Feature::Skirt:
            return "skirt_brim";
        case Feature::PrimeTower:
            return "prime_tower";
    }
    return "print";
}

/// `prefix`_`suffix` on `layer`, blended from `prefix`_`first` over the slow-down layers.
double layerValue(const Settings& s, const std::string& prefix, const std::string& suffix,
                  const std::string& first, int layer, bool smooth) {
    const double value = s.real(prefix + "_" + suffix);
    if (!smooth)
        return value;
    const double initial = s.real(prefix + "_" + first);
    const long long slowdown = s.has("speed_slowdown_layers") ? s.integer("speed_slowdown_layers") : 0;
    if (layer <= 0)
        return initial;
    if (layer >= slowdown)
        return value;
    const double t = double(layer) / double(slowdown);
    return initial + (value - initial) * t;
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
    const std::string suffix = travel ? "travel" : featureSuffix(at.feature);
    const std::string first = travel ? "travel_layer_0" : "print_layer_0";
    const bool smooth = travel || at.feature != Feature::Skirt;
    if (sources.acceleration_enabled)
        step.acceleration_mm_s2 = layerValue(s, "acceleration", suffix, first, layer, smooth);
    if (sources.jerk_enabled)
        step.jerk_mm_s = layerValue(s, "jerk", suffix, first, layer, smooth);
}

}  // namespace

MotionSources motionSources(const Settings& global, std::vector<const Settings*> meshes,
                            const std::vector<Settings>& extruders) {
    MotionSources sources;
    sources.acceleration_enabled =
        global.has("acceleration_enabled") && global.boolean("acceleration_enabled");
    sources.jerk_enabled = global.has("jerk_enabled") && global.boolean("jerk_enabled");
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
