#pragma once
// Prime tower and ooze shield of a multi-extruder mesh group.
//
// Prime tower (prime_tower_enable, with at least two extruders printing; off, as in CuraEngine,
// when prime_tower_size or prime_tower_min_volume is not above 10 µm / 10 µm³): a disc of diameter
// prime_tower_size centred at (prime_tower_position_x − size/2, prime_tower_position_y + size/2) as
// CuraEngine places it (a 32-gon), moved by the brim width towards x = y = 0 with
// prime_tower_brim_enable (not with a raft). Every extruder of the machine has its own rings, in
// the order of material_adhesion_tendency (lowest outermost; ties by number): concentric loops of
// prime_tower_line_width, one line width apart, inside the rings of the extruders before it, until
// they hold prime_tower_min_volume (mm³, width × layer_height × flow). The rings are made for every
// layer up to one above the last on which two or more extruders print; planning prints an
// extruder's rings on a layer when it switches to it there, and the outermost extruder's on every
// layer up to that last one (planning/PrintPlanner.h), as CuraEngine. On layer 0 only the outermost
// extruder prints: concentric loops filling the whole disc. Feature PrimeTower, speed
// speed_prime_tower, flow prime_tower_flow, per-extruder values from that extruder's train.
// prime_tower_brim_enable: brim_line_count brim lines around the tower on layer 0 (adhesion's
// extruder, style and skirt_brim_minimal_length), which the model's brim then leaves out.
//
// Ooze shield (ooze_shield_enabled): on the same layers, one loop around everything on the layer
// at ooze_shield_dist (outer contours only), widened so that it never leans more than
// ooze_shield_angle (going up or down it shrinks at most layer_height · tan(angle) per layer).
// Printed as Feature Skirt by the lowest-numbered extruder printing on the layer.
#include <set>
#include <vector>

#include "settings/Settings.h"
#include "slicing/LayerHeights.h"
#include "toolpaths/core/ExtrusionPath.h"

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

/// The tower's outline (empty when disabled), moved for its brim (`global`: the group's settings).
Path primeTowerOutline(const Settings& global, const std::vector<Settings>* extruders = nullptr);

struct PrimeTowerResult {
    std::vector<std::vector<ExtrusionPath>> layers;  ///< [layer] every extruder's rings
    std::vector<ExtrusionPath> brim;                 ///< its own brim on layer 0 (prime_tower_brim_enable)
    int outermost = -1;                              ///< the extruder of the outer rings
    int last_forced_layer = -1;                      ///< the outermost prints its rings up to here
    Point2 middle{0, 0};                             ///< the tower's centre (where the wipe goes)
};

PrimeTowerResult generatePrimeTower(const TowerInput& input);
std::vector<std::vector<ExtrusionPath>> generateOozeShield(const TowerInput& input);

}  // namespace mixengine
