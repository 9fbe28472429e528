#pragma once
// Visits to the purge tower (mixing/transition/PurgeTower.h), shared by the transition planners
// (mixing/transition/TransitionPlan.h): the tower sized and placed for the largest layer purge, one layer's
// cursor on its zigzag, and the steps of one visit — the ;MESH:/;TYPE: markers of the tower, its extrusions,
// and what brings the print back to where it was.
#include <cstddef>
#include <optional>
#include <vector>

#include "mixing/transition/PurgeTower.h"
#include "mixing/transition/TransitionPlan.h"

namespace mixengine {

/// A layer's thickness: its own, or the distance to the layer below (the first layer's z).
coord_um thicknessOf(const PrintPlan& plan, std::size_t l);

/// One layer's tower: the cursor on its zigzag and the travel and extrusion steps its visits copy.
struct LayerTower {
    TowerCursor cursor;
    PlanStep travel, extrude;
};

struct TowerPlan {
    PurgeTowerShape shape;
    std::size_t last_layer = 0;  ///< the last layer that prints the tower
};

/// The tower for purges of `needed[l]` mm³ on layer l: a square big enough for the largest per mm of
/// layer height, placed clear of the print (and of `settings.keep_clear`); empty when nothing is needed,
/// the tower is off, or there is no room (then a warning in `report`).
std::optional<TowerPlan> sizeTower(const PrintPlan& plan, const std::vector<double>& needed,
                                   TransitionSettings settings, TransitionReport& report);

/// Layer l's tower, or nothing above the tower's last layer (or in a layer without travel to copy).
std::optional<LayerTower> layerTower(const PrintPlan& plan, std::size_t l,
                                     const std::optional<TowerPlan>& tower,
                                     const TransitionSettings& settings);

/// Appends to `out` the steps of one visit that purges `volume_mm3` of `mix` before `steps[at]`, and the
/// steps that bring the print back to where it stood there.
void visitTower(LayerTower& tower, double volume_mm3, int mix, const std::vector<PlanStep>& steps,
                std::size_t at, std::vector<PlanStep>& out);

}  // namespace mixengine
