#pragma once
// Where tree support branches may not be (toolpaths/support/TreeSupport.h), per branch radius and layer,
// computed when first asked for and kept (CuraEngine 4.13's rules):
//   collision(r, n)  the model on layer n grown by the X/Y distance and by r. With
//                    support_xy_overrides_z z_overrides_xy, the smaller
//                    support_xy_distance_overhang next to what overhangs z_layers up (the model
//                    z_layers up less this layer) and nothing on the top z_layers layers;
//   avoidance(r, n)  collision(r, n) united with avoidance(r, n−1) shrunk by the distance a
//                    branch may move per layer: a branch of radius r outside it can still reach
//                    the build plate going down without touching the model.
// Radii are rounded up to a multiple of the collision resolution. Not thread-safe: one caller.
#include <map>
#include <vector>

#include "geometry/Point.h"

namespace mixengine {

struct TreeVolumeParams {
    coord_um xy_distance_um = 800;
    coord_um xy_distance_overhang_um = 400;
    bool z_overrides_xy = false;
    int z_layers = 2;              ///< ceil(support_top_distance / layer_height) + 1
    coord_um max_move_um = 0;      ///< a branch's largest step per layer
    coord_um resolution_um = 200;  ///< support_tree_collision_resolution
};

class TreeVolumes {
  public:
    /// `model[n]`: every mesh's outlines on layer n.
    TreeVolumes(const std::vector<Paths>* model, TreeVolumeParams params);

    const Paths& collision(coord_um radius_um, int layer);
    const Paths& avoidance(coord_um radius_um, int layer);
    coord_um roundedRadius(coord_um radius_um) const;

  private:
    Paths computeCollision(coord_um radius_um, int layer) const;
    /// Sizes a radius' cache (`areas`, `done`) to the model's layers once; whether `layer` is one of them.
    bool sizedForLayer(std::vector<Paths>& areas, std::vector<bool>& done, int layer) const;

    const std::vector<Paths>* model_;
    TreeVolumeParams params_;
    std::map<coord_um, std::vector<Paths>> collision_;  ///< radius → [layer] (filled on demand)
    std::map<coord_um, std::vector<Paths>> avoidance_;
    std::map<coord_um, std::vector<bool>> collision_done_, avoidance_done_;
};

}  // namespace mixengine
