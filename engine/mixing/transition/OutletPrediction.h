#pragma once
// What leaves the nozzle (issue 26): the plan's commanded mixes pushed through the chamber model
// (mixing/chamber/ChamberModel.h) in print order, the chamber full of the first commanded mix at the start
// (the start code primes it). Every extrusion gets the colour the pigment model
// (mixing/color/KubelkaMunk.h) predicts for the mix that leaves the nozzle while it prints — the average
// over its own volume — as PlanStep::outlet_color (the previews and ;PREDICTED_COLOR: show it), and
// the visible surface (mixing/transition/LayerOrder.h visibleFeature: outer walls, skin, ironing) is measured
// against what each extrusion asked for: by length, the share within ΔE00 ≤ 3 and the share within
// the transition tolerance, and the worst place.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "mixing/chamber/ChamberModel.h"
#include "mixing/color/KubelkaMunk.h"
#include "mixing/transition/LayerOrder.h"

namespace mixengine {

inline constexpr double kVisibleDeltaE00 = 3.0;

struct VisiblePlace {
    double delta_e00 = -1;  ///< −1: no visible extrusion
    double share_distance = 0;
    int layer = 0;  ///< ;LAYER: number
    Point2 at{};
    Feature feature = Feature::WallOuter;
};

/// Lengths of visible extrusion (mm): all, within ΔE00 ≤ kVisibleDeltaE00, within the tolerance.
struct VisibleFigure {
    double visible_mm = 0, within_de_mm = 0, within_share_mm = 0;
};

struct VisibleReport {
    double visible_mm = 0;       ///< length of the visible extrusions
    double within_de_mm = 0;     ///< of which within ΔE00 ≤ kVisibleDeltaE00 of what they asked
    double within_share_mm = 0;  ///< of which within the tolerance (shareDistance)
    VisiblePlace worst;
    std::map<int, VisibleFigure> by_mesh;  ///< by PlanStep::mesh_index (this group's meshes only)
    void add(const VisibleReport& other);
};

/// Sets PlanStep::outlet_color of every extrusion of `plan` and fills plan.outlet_colors.
/// `targets[l][i]`: what step i of layer l asked for; `chamber` carries over from earlier groups
/// (empty: full of the first commanded mix).
VisibleReport predictOutlet(PrintPlan& plan, const std::vector<std::vector<StepTarget>>& targets,
                            std::optional<Chamber>& chamber, const ChamberSpec& spec, double tolerance,
                            const PigmentModel& model);

}  // namespace mixengine
