#pragma once
// The purge tower (issue 26): a solid square beside the print that takes what a change of mix needs
// beyond what the model's hidden volume absorbs. Every layer from the first up to the last one that
// purges prints the whole square (so it stands), as a zigzag of lines one line width apart: along X on
// even layer numbers, along Y on odd ones. The square is sized so that its largest layer purge fits.
#include <optional>
#include <vector>

#include "planning/LayerPlan.h"

namespace mixengine {

struct PurgeTowerShape {
    Point2 min_corner{};  ///< microns, the plan's frame
    coord_um side_um = 0;
    coord_um line_width_um = 400;
};

/// Where the tower may stand: the machine's plate and the rectangle the print covers.
struct TowerSite {
    Point2 plate_min{}, plate_max{};
    Point2 print_min{}, print_max{};
    /// Cura's prime tower position (prime_tower_position_x/y): the square's max-X, min-Y corner
    std::optional<Point2> preferred_anchor;
    coord_um clearance_um = 3000;  ///< kept free around the print
};

/// The min corner of the first place, of the preferred anchor and the four sides of the print, where a square
/// of `side_um` fits on the plate clear of the print; nothing when there is none.
std::optional<Point2> placeTower(const TowerSite& site, coord_um side_um);

/// The zigzag of one layer of the tower.
Path towerPath(const PurgeTowerShape& shape, int layer_number);

/// Hands out one layer's tower path by volume.
class TowerCursor {
  public:
    TowerCursor(Path path, coord_um line_width_um, coord_um thickness_um);
    double volumeLeftMm3() const;
    /// Steps that extrude `volume_mm3` (at most what is left) from where the last call stopped: a
    /// copy of `travel` (retracting) to there, then copies of `extrude` along the path.
    void emit(double volume_mm3, const PlanStep& travel, const PlanStep& extrude, std::vector<PlanStep>& out);

  private:
    Path path_;
    double mm3_per_um_;
    std::size_t segment_ = 0;  ///< the path segment [segment_, segment_ + 1] the cursor is on
    Point2 at_{};
    double left_mm3_ = 0;
};

}  // namespace mixengine
