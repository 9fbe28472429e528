#pragma once
// Support towers (Cura's support_use_towers), as CuraEngine 4.13 builds them:
//   - overhang points: on layer n, a part of a mesh whose outer contour is smaller than
//     support_tower_maximum_supported_diameter² and that touches nothing of that mesh on layer n−1,
//     inset by half a line width and less the support blockers;
//   - a tower roof starts one layer below each point (those with a point of the layer below within
//     twice the maximum diameter are left to that one), and also under a small support island (area
//     below the maximum diameter²) whose middle has support six layers up and no model
//     six + bottom_gap layers down (on every layer while the island stays that small, so a column
//     of staggered roofs ends somewhat wider than the diameter, as CuraEngine's);
//   - each roof is added to the support of its layer and, going down, grows by
//     layer_height / tan(support_tower_roof_angle) per layer until its area reaches
//     support_tower_diameter²; from there the ordinary support carries it down to the plate.
#include <vector>

#include "geometry/Point.h"
#include "slicing/Slicer.h"

namespace mixengine {

struct SupportTowerParams {
    coord_um max_supported_diameter_um = 0;  ///< 0: no towers
    coord_um diameter_um = 0;
    coord_um roof_step_um = 0;  ///< growth of a roof per layer going down
};

/// Per layer the overhang points of one mesh (see above); `blockers` may be null.
std::vector<std::vector<Paths>> detectOverhangPoints(const std::vector<SlicedLayer>& layers,
                                                     coord_um max_diameter_um, coord_um inset_um,
                                                     const std::vector<Paths>* blockers);

/// The growing tower roofs, walked from the top layer down.
class TowerRoofs {
  public:
    explicit TowerRoofs(const SupportTowerParams& params) : params_(params) {}

    /// Starts a roof for each of `points` (those of the layer above the one being built) not within
    /// twice the maximum diameter of `points_below` (the points one layer lower).
    void startAt(const std::vector<Paths>& points, const std::vector<Paths>& points_below);

    /// Starts a roof for each small island of `support` (this layer's) whose middle lies in
    /// `support_above` (six layers up) and not in `model_below` (six + bottom_gap layers down).
    void startUnderSmallIslands(const Paths& support, const Paths& support_above, const Paths& model_below);

    /// Every live roof united into `area`; then each grows one step, or ends when big enough.
    void addTo(Paths& area);

    /// How many layers above a small support island to look for support (CuraEngine's choice).
    static constexpr int kSmallIslandLookLayers = 6;

  private:
    SupportTowerParams params_;
    std::vector<Paths> roofs_;
};

}  // namespace mixengine
