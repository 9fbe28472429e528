#pragma once
// The toolpath stage for one mesh group: from the sliced outlines of every mesh to typed extrusion
// lines per layer — each mesh's walls, skin and infill, the support, and the skirt or brim.
//
// Contract: plain data in, plain data out. Every ExtrusionPath carries the extruder that prints it
// (the mesh's extruder_nr or a feature's *_extruder_nr), its width, speed and feature. Paths are
// grouped, not yet ordered: ordering, travel and retraction belong to planning. Wall loops with a
// chosen seam start at points.front() and have fixed_start set.
//
// Order of work: each mesh (toolpaths/MeshToolpaths.h; infill meshes inside the others,
// toolpaths/InfillMeshes.h), then the support around all meshes
// (toolpaths/support/Support.h), the prime tower and ooze shield for the extruders in use
// (toolpaths/adhesion/PrimeTower.h), the draft shield (toolpaths/adhesion/DraftShield.h), and last the skirt
// or brim around everything on layer 0 (toolpaths/adhesion/Adhesion.h) with the other extruders' lines
// outside it (toolpaths/adhesion/ExtruderSkirts.h); last, the empty layers at the bottom are dropped
// (toolpaths/EmptyLayers.h), so layer 0 of the result is the first layer that prints. With adhesion_type raft
// there is no skirt or brim: the raft (toolpaths/adhesion/Raft.h) goes under everything on that first layer,
// the first layer's support moves to the raft's filler layers (toolpaths/support/Support.h) and the model's
// heights are lifted (toolpaths/adhesion/RaftLayout.h). `threads` is used inside every step; the result
// does not depend on it.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "settings/Settings.h"
#include "slicing/LayerHeights.h"
#include "slicing/MultiVolumes.h"
#include "slicing/Slicer.h"
#include "toolpaths/MeshToolpaths.h"
#include "toolpaths/adhesion/Raft.h"

namespace mixengine {

struct ToolpathMeshInput {
    const Settings* settings = nullptr;                ///< the mesh's resolved settings
    std::string name;                                  ///< for ;MESH:
    const std::vector<SlicedLayer>* layers = nullptr;  ///< index = layer
    /// The mesh's bounding box in x and y (its middle is the infill pattern's origin; the cross
    /// fractal's square is laid around it); unset: its outlines' bounds.
    std::optional<Box2> box_um;
    /// A model, or a modifier of the others (infill mesh, support mesh, support blocker;
    /// toolpaths/InfillMeshes.h, toolpaths/support/Support.h). Cutting meshes arrive carved and print as
    /// models.
    VolumeRole role;
};

struct ToolpathInput {
    const Settings* global = nullptr;                  ///< the group's settings
    const std::vector<Settings>* extruders = nullptr;  ///< resolved extruder trains, index = extruder_nr
    std::vector<LayerZ> heights;
    std::vector<ToolpathMeshInput> meshes;
    /// Hears the share of the meshes' walls, skin and infill done, 0..1, from any thread; may throw
    /// to stop the stage (the exception leaves generateGroupToolpaths). Empty: nothing hears.
    std::function<void(double share_done)> on_progress;
};

struct MeshToolpaths {
    const Settings* settings = nullptr;
    std::string name;
    std::vector<MeshLayerGroups> layers;  ///< index = layer
    /// The mesh's sliced layers (the input's); sliced layer first_sliced_layer + i is layer i. Null
    /// for modifier meshes (infill meshes, support meshes, support blockers).
    const std::vector<SlicedLayer>* sliced = nullptr;
};

struct GroupToolpaths {
    /// [layer] the heights to print at: the input's, less one entry from the top per empty bottom
    /// layer dropped (the print starts at the first layer's height, as CuraEngine), lifted by the
    /// raft when there is one (print_z and bottom_z alike: the layers keep their thickness).
    std::vector<LayerZ> heights;
    /// The sliced layer printed as layer 0: the number of empty bottom layers dropped.
    std::size_t first_sliced_layer = 0;
    std::vector<MeshToolpaths> meshes;
    std::vector<std::vector<ExtrusionPath>> support;  ///< [layer]; support and its interface
    std::vector<ExtrusionPath> adhesion;              ///< skirt or brim, printed first on layer 0
    /// [layer]; the prime tower's rings for every extruder (ExtrusionPath::extruder), printed by an
    /// extruder right after it becomes active on that layer, and by prime_tower_outermost on every
    /// layer up to prime_tower_last_forced_layer (toolpaths/adhesion/PrimeTower.h). Empty without a tower.
    std::vector<std::vector<ExtrusionPath>> prime_tower;
    int prime_tower_outermost = -1;
    int prime_tower_last_forced_layer = -1;
    Point2 prime_tower_middle{0, 0};  ///< where the wipe after a switch goes (prime_tower_wipe_enabled)
    std::vector<std::vector<ExtrusionPath>> ooze_shield;  ///< [layer]; empty without an ooze shield
    /// [layer] the draft shield (toolpaths/adhesion/DraftShield.h); empty lists without one.
    std::vector<std::vector<ExtrusionPath>> draft_shield;
    /// The layers printed below the model, in print order with CuraEngine's negative numbers: the
    /// raft's base, interface and surface layers, then its filler layers when the first layer has
    /// support. Empty without a raft.
    std::vector<RaftLayer> raft;
    Paths raft_outline;  ///< what the raft covers (travel on the layers below the model combs in it)
    /// Settings the stage could not honour (e.g. adhesion_type raft printed as a skirt), one line
    /// each, for the caller to log.
    std::vector<std::string> warnings;
    /// Information for the caller to log (the empty bottom layers removed), one line each.
    std::vector<std::string> notes;
};

GroupToolpaths generateGroupToolpaths(const ToolpathInput& input, int threads);

}  // namespace mixengine
