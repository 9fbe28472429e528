#pragma once
// The layer view Cura draws in its Preview stage: each planned layer → one LayerOptimized message
// (shared/reference/cura-integration.md §5.3).
//
// Units on the wire: layer height and thickness in microns; points (float32 x, y) and line
// widths/thicknesses in mm; feedrates in mm/s. A PathSegment holds one extruder's consecutive
// moves, N + 1 points for N lines, each line typed with Cura's Polygon.Type numbers
// (1 outer wall … 8 combing travel, 9 retracted travel, 11 prime tower). Points are where the
// material lands on the plate (the plan's frame, before any nozzle offset is applied).
#include <memory>
#include <vector>

#include "planning/LayerPlan.h"

namespace cura::proto {
class LayerOptimized;
}

namespace mixengine {

/// Cura's line type number of a feature (Polygon.Type).
int curaLineType(Feature feature);

/// One message per layer of `plan`, its id the layer's index plus `index_offset` (raft layers are
/// negative, as CuraEngine sends them; Cura's layer view shifts them up) and its thickness the
/// layer's (PlannedLayer::thickness, else the distance to the layer below). The head starts at
/// `start` with extruder `start_extruder`; both are advanced to where the plan leaves them.
std::vector<std::shared_ptr<cura::proto::LayerOptimized>> previewLayers(const PrintPlan& plan,
                                                                        int index_offset, Point2& start,
                                                                        int& start_extruder);

/// Where the preview of a stream of layers stands: the head, its extruder, and the height of the
/// layer before (0 at the start of a mesh group).
struct PreviewCursor {
    Point2 head{0, 0};
    int extruder = 0;
    coord_um previous_z = 0;
};

/// One layer's message, as previewLayers() makes it for that layer, with the id `id`; advances
/// `cursor`.
std::shared_ptr<cura::proto::LayerOptimized> previewLayer(const PlannedLayer& planned, int id,
                                                          PreviewCursor& cursor);

}  // namespace mixengine
