#include "planning/LayerWipes.h"

#include <algorithm>

namespace mixengine {
namespace {

/// Whether the layer switches extruder before it extrudes or travels anywhere but to an end position.
bool switchesFirst(const PlannedLayer& layer) {
    for (const PlanStep& step : layer.steps) {
        if (step.kind == PlanStep::Kind::SetExtruder)
            return true;
        if (step.kind == PlanStep::Kind::Extrude)
            return false;
    }
    return false;
}

}  // namespace

LayerWipeParams layerWipeParams(const Settings& extruder) {
    LayerWipeParams p;
    p.enabled = extruder.boolean(key::clean_between_layers);
    p.max_extrusion_mm3 = extruder.real(key::max_extrusion_before_wipe);
    return p;
}

void planLayerWipes(PrintPlan& plan, const std::vector<LayerWipeParams>& per_extruder, int extruder) {
    if (std::none_of(per_extruder.begin(), per_extruder.end(),
                     [](const LayerWipeParams& p) { return p.enabled; }))
        return;  // no train wipes
    std::vector<double> since_wipe(per_extruder.size(), 0.0);
    auto train = [&](int e) {
        return std::min<std::size_t>(static_cast<std::size_t>(std::max(e, 0)), per_extruder.size() - 1);
    };
    for (PlannedLayer& layer : plan.layers) {
        const std::size_t active = train(extruder);
        if (per_extruder[active].enabled && !switchesFirst(layer) &&
            since_wipe[active] > per_extruder[active].max_extrusion_mm3) {
            if (layer.layer_change_retract_step >= 0)
                layer.steps[static_cast<std::size_t>(layer.layer_change_retract_step)].retract = false;
            layer.layer_change_retract_step = -1;
            PlanStep wipe;
            wipe.kind = PlanStep::Kind::WipeScript;
            wipe.extruder = static_cast<int>(active);
            layer.steps.insert(layer.steps.begin(), wipe);
            since_wipe[active] = 0;
        }
        for (const PlanStep& step : layer.steps) {
            if (step.kind == PlanStep::Kind::SetExtruder) {
                since_wipe[train(extruder)] = 0;  // as CuraEngine: switching away restarts the count
                extruder = step.extruder;
            } else if (step.kind == PlanStep::Kind::Extrude) {
                since_wipe[train(extruder)] += step.volume_mm3;
            }
        }
    }
}

}  // namespace mixengine
