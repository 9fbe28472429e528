#pragma once
// Tree support (support_structure tree), as CuraEngine 4.13 builds it: branches from contact
// points under the overhangs (toolpaths/support/TreeNodes.h) go down layer by layer, leaning at most
// support_tree_angle from vertical, merging with their neighbours and keeping out of the model
// (toolpaths/support/TreeVolumes.h, support_tree_collision_resolution), to the build plate or, with
// support_type everywhere, onto the model. Each node is drawn as a 10-sided circle:
//   - tip: over the first (branch radius − 0.75 · support_line_width) / layer_height layers below
//     the contact the circle (support_tree_branch_diameter / 2) is flattened across one diagonal,
//     from 0.75 line widths at the contact to the full radius;
//   - below, the radius grows by sin(support_tree_branch_diameter_angle) · layer_height per layer;
//   - the top support_roof_height of each branch is roof (support_roof_enable);
//   - floor (support_bottom_enable): where the support stands on the model
//     support_bottom_distance + up to support_bottom_height below (sampled every
//     support_interface_skip_height), less the floor grown by 10 µm from the body.
// The areas are filled as normal support is (toolpaths/support/SupportPaths.h).
#include <vector>

#include "settings/Settings.h"
#include "toolpaths/support/SupportAreas.h"

namespace mixengine {

struct TreeMesh {
    const Settings* settings = nullptr;  ///< support_tree_branch_distance, support_angle, roof, top distance
    const std::vector<Paths>* overhang = nullptr;  ///< [layer] the mesh's overhang (Overhangs::basic)
    Box2 bounds{0, 0, 0, 0};                       ///< the mesh's bounds in x and y
};

/// The tree support areas per layer. `group`: the mesh group's settings (branch diameter and
/// angle, tree angle, collision resolution, X/Y and Z distances, floor); `model[n]`: every mesh's
/// outlines on layer n.
std::vector<SupportLayerAreas> treeSupportAreas(const Settings& group, const std::vector<TreeMesh>& meshes,
                                                const std::vector<Paths>& model, int threads);

}  // namespace mixengine
