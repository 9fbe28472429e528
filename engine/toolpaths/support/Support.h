#pragma once
// Support for one mesh group: overhangs of every mesh with support_enable (its own support_angle) less
// the support blockers, the support meshes (SupportMesh::role),
// support areas (toolpaths/support/SupportAreas.h) around all meshes, and their lines
// (toolpaths/support/SupportPaths.h). The support keys are read from the extruder train that prints the
// support infill (support_infill_extruder_nr; on layer 0 support_extruder_nr_layer_0), the
// interfaces' from support_roof_extruder_nr / support_bottom_extruder_nr, as CuraEngine does.
//
// Under a raft (SupportInput::raft), as CuraEngine 4.13: the model's first layer prints no support;
// the first layer's support area is printed on the raft's filler layers instead (SupportResult::
// filler: as on layer 0 — grid, one wall more — but at support_line_distance, the regular speed and
// flow and without initial_layer_line_width_factor), and no line width on layer 0 is widened.
//
// Support brim (support_brim_enable of the support infill train, no raft), as CuraEngine 4.13:
// support_brim_line_count loops inside the support body's first-layer outline, the first w/2 in,
// one width apart (w = skirt_brim_line_width × initial_layer_line_width_factor, round joins; holes
// smaller than 100 w² dropped), printed with the skirt/brim (Feature Skirt, the skirt's speed and
// flow); the first layer's support is what lies farther inside than count × w.
#include <vector>

#include "settings/Settings.h"
#include "slicing/LayerHeights.h"
#include "slicing/MultiVolumes.h"
#include "slicing/Slicer.h"
#include "toolpaths/core/ExtrusionPath.h"
#include "toolpaths/support/SupportAreas.h"

namespace mixengine {

struct SupportMesh {
    const Settings* settings = nullptr;
    const std::vector<SlicedLayer>* layers = nullptr;
    /// Models with support_enable have their overhangs supported; a support mesh (support_mesh) is
    /// support where it is — carried down to the plate or the model with support_mesh_drop_down —
    /// even without support_enable; a support blocker (anti_overhang_mesh) takes its volume out of
    /// every overhang, so nothing under it is supported for it. Infill meshes take no part.
    VolumeRole role;
    /// `layers` with the print outlines as outlines (toolpaths/MeshToolpaths.h:
    /// MeshLayerGroups::print_outline), whose overhangs are supported, as CuraEngine 4.13; null: `layers`.
    const std::vector<SlicedLayer>* print_outlines = nullptr;
};

struct SupportInput {
    const Settings* global = nullptr;
    const std::vector<Settings>* extruders = nullptr;  ///< may be null or empty: global is used
    const std::vector<LayerZ>* heights = nullptr;
    std::vector<SupportMesh> meshes;
    /// [layer] all meshes' outlines united; their print outlines where they have them (as SupportMesh)
    const std::vector<Paths>* model = nullptr;
    bool raft = false;  ///< adhesion_type raft (see above)
    /// Where layer 0 has no support body or roof (brimCoveredArea: the brim replaces it).
    Paths first_layer_exclusion;
};

struct SupportResult {
    std::vector<std::vector<ExtrusionPath>> paths;  ///< [layer]; all empty without support_enable
    Paths first_layer_area;                         ///< the support's area on layer 0 (for the brim)
    std::vector<ExtrusionPath> filler;              ///< raft only: the paths of every raft filler layer
    std::vector<ExtrusionPath> brim;                ///< the support brim (see above), outermost first
    std::vector<SupportLayerAreas> areas;           ///< [layer] the areas printed (empty without support)
};

SupportResult generateSupport(const SupportInput& input, int threads);

/// brim_replaces_support (of the support infill extruder) with adhesion_type brim, as CuraEngine
/// 4.13: the model's layer-0 outlines (outer contours only with brim_outside_only, whose holes keep
/// their support) grown by skirt_brim_line_width × initial_layer_line_width_factor ×
/// brim_line_count rounded up to even; the support's first layer leaves that to the brim. Empty
/// otherwise.
Paths brimCoveredArea(const Settings& global, const std::vector<Settings>* extruders, const Paths& layer0);

/// The settings of extruder train `nr` (the global settings when there is none such).
const Settings& trainSettings(const Settings& global, const std::vector<Settings>* extruders, int nr);

}  // namespace mixengine
