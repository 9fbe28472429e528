#pragma once
// Prime tower and ooze shield of a multi-extruder mesh group.
//
// Prime tower (prime_tower_enable, with at least two extruders printing): a disc of diameter
// prime_tower_size centred at (prime_tower_position_x − size/2, prime_tower_position_y + size/2)
// as CuraEngine places it (a 32-gon). On every layer up to the last one on which two or more
// extruders print, each extruder printing on the layer gets its own rings, outermost extruder
// (lowest number) outside: concentric loops of prime_tower_line_width, one line width apart,
// until they hold prime_tower_min_volume (mm³, width × layer_height × flow). On layer 0 the first
// extruder fills the whole disc and the others print nothing there (as CuraEngine 4.13 does).
// Feature PrimeTower, speed speed_prime_tower,
// flow prime_tower_flow, per-extruder values from that extruder's train.
//
// Ooze shield (ooze_shield_enabled): on the same layers, one loop around everything on the layer
// at ooze_shield_dist (outer contours only), widened so that it never leans more than
// ooze_shield_angle (going up or down it shrinks at most layer_height · tan(angle) per layer).
// Printed as Feature Skirt by the lowest-numbered extruder printing on the layer.
#include <set>
#include <vector>

#include "settings/Settings.h"
#include "slicing/LayerHeights.h"
#include "toolpaths/ExtrusionPath.h"

namespace mixengine {

struct TowerInput {
    const Settings* global = nullptr;
    const std::vector<Settings>* extruders = nullptr;
    const std::vector<LayerZ>* heights = nullptr;
    std::vector<std::set<int>> used;            ///< [layer] extruders printing on the layer
    const std::vector<Paths>* model = nullptr;  ///< [layer] everything on the layer (for the shield)
};

/// Layers that get a prime tower / ooze shield: up to the last layer with two or more extruders
/// printing (−1: none).
int lastMultiExtruderLayer(const std::vector<std::set<int>>& used);

/// The tower's outline (empty when disabled).
Path primeTowerOutline(const Settings& global);

std::vector<std::vector<ExtrusionPath>> generatePrimeTower(const TowerInput& input);
std::vector<std::vector<ExtrusionPath>> generateOozeShield(const TowerInput& input);

}  // namespace mixengine
