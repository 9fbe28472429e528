#pragma once
// The nodes of tree support (toolpaths/support/TreeSupport.h): where branches touch the model, and how
// they go down layer by layer (CuraEngine 4.13's rules).
//
// Contact points: a grid of points support_tree_branch_distance apart, turned 22° about the
// middle of the mesh's bounds; on layer n, the grid points in (or up to half an overhang step,
// tan(support_angle) · layer_height / 2, from) each overhang loop of layer n + z_layers that are
// not in collision(0, n); a loop that catches none gets one point (the bounds' middle moved onto
// it); points in holes of the overhang are dropped. A contact starts support_roof_height /
// layer_height layers of roof (support_roof_enable).
//
// Dropping, from the top layer down to layer 1: the nodes of a layer are grouped — those that
// can reach the build plate in one group, the others by the island of avoidance(0) they are in or
// nearest to — and each group is joined by its minimum spanning tree. Two nodes alone in a group
// and closer than the largest step become one node half way; a node with several neighbours
// swallows those closer than the largest step. Every other node moves towards its neighbours
// (their summed direction, at most the largest step; a leaf closer than that does not move), and
// a node that can reach the plate is then pushed out of avoidance(its radius, the layer below).
// A node in a group resting on the model ends where it is deeper inside collision(0) than its
// radius. With support_type buildplate a branch that cannot reach the plate is removed whole.
#include <cstddef>
#include <vector>

#include "geometry/Point.h"
#include "toolpaths/support/TreeVolumes.h"

namespace mixengine {

struct TreeNode {
    Point2 position{0, 0};
    int distance_to_top = 0;      ///< layers below its contact point
    bool skin_direction = false;  ///< which diagonal the tip is flattened across
    int roof_layers_below = 0;    ///< > 0: this layer of the branch is roof
    bool to_buildplate = true;
    bool removed = false;
    std::vector<std::size_t> sources;  ///< nodes of the layer above that went into this one
};

using TreeLayers = std::vector<std::vector<TreeNode>>;  ///< [layer] the nodes on it

struct TreeContactParams {
    coord_um branch_distance_um = 1000;
    int z_layers = 2;
    int roof_layers = 0;
    coord_um half_overhang_step_um = 100;
};

/// Adds the contact points of one mesh. `overhang[n]`: the mesh's overhang on layer n; `bounds`:
/// the mesh's bounds in x and y.
void addContactPoints(const std::vector<Paths>& overhang, const Box2& bounds, const TreeContactParams& params,
                      TreeVolumes& volumes, TreeLayers& layers);

struct TreeDropParams {
    coord_um max_move_um = 0;
    coord_um branch_radius_um = 1000;
    double radius_growth_per_layer = 0;  ///< sin(diameter angle) · layer_height / branch radius
    coord_um resolution_um = 200;
    bool rests_on_model = true;  ///< support_type everywhere
};

/// The radius a branch has `distance_to_top` layers below its tip, while dropping.
coord_um droppingRadius(const TreeDropParams& params, coord_um layer_height_um, int distance_to_top);

void dropNodes(const TreeDropParams& params, coord_um layer_height_um, TreeVolumes& volumes,
               TreeLayers& layers);

}  // namespace mixengine
