#pragma once
// Skirt and brim on the first layer (Cura's adhesion_type and its keys):
//   skirt — loops around the approximate convex hull (DraftShield.h) of everything on layer 0
//           (models, support, prime tower), closed by 20 µm and simplified as CuraEngine 4.13 does: the first
//           skirt_gap + w/2 outside it, then one line width further out each, at least skirt_line_count loops
//           and more until they total skirt_brim_minimal_length;
//   brim  — loops around the models' (and the support's) layer-0 outlines — without the islands too thin
//           for an outer wall, which CuraEngine drops — grown by brim_gap (mitred),
//           united, closed by 20 µm and simplified as CuraEngine 4.13 does (with brim_outside_only
//           without the holes that hold nothing): the first w/2 outside that, brim_line_count of them
//           (more while shorter than skirt_brim_minimal_length), each without its holes under 100 w²;
//   shields — with a draft or ooze shield (AdhesionInput::shields) the skirt goes around the
//           approximate convex hull of the shields and of the hull grown by skirt_gap − w/2, its
//           first loop w outside that; a brim fills the shields' foot from the inside with loops one
//           line width apart, brim_line_count rounded up to even widths deep, short of the brim
//           around the models by a line width;
//   none  — nothing; raft — nothing here either (toolpaths/adhesion/Raft.h builds it); any other value
//           prints a skirt and the caller is warned.
// w = skirt_brim_line_width × initial_layer_line_width_factor; speed skirt_brim_speed; flow
// skirt_brim_material_flow × material_flow_layer_0; extruder adhesion_extruder_nr
// (skirt_brim_extruder_nr when the machine has it); Feature Skirt. Outermost loop first. Every loop is
// simplified afterwards with meshfix_maximum_resolution / _deviation (simplifyAdhesion).
#include <string>
#include <vector>

#include "geometry/Point.h"
#include "settings/Settings.h"
#include "toolpaths/core/ExtrusionPath.h"

namespace mixengine {

struct AdhesionInput {
    const Settings* global = nullptr;
    const std::vector<Settings>* extruders = nullptr;
    Paths models;   ///< every mesh's layer-0 outlines and the support's layer-0 area
    Paths extras;   ///< points of other things on layer 0 the skirt goes around (support, tower)
    Paths shields;  ///< the draft shield's and the ooze shield's first-layer outlines
};

struct AdhesionResult {
    std::vector<ExtrusionPath> paths;
    std::vector<std::string> warnings;
};

AdhesionResult generateAdhesion(const AdhesionInput& input);

/// As CuraEngine 4.13 finishes its skirt and brim lines (every extruder's skirt or brim, the support's
/// and the prime tower's brim): each loop simplified with the adhesion extruder's
/// meshfix_maximum_resolution / _deviation (slicing/OutlineCleanup.h simplifyLoop); a loop left with
/// fewer than three vertices goes. Open paths are kept as they are.
void simplifyAdhesion(const Settings& global, const std::vector<Settings>* extruders,
                      std::vector<ExtrusionPath>& paths);

/// Convex hull of all points of `polygons`, counter-clockwise (empty for no points).
Path convexHull(const Paths& polygons);

}  // namespace mixengine
