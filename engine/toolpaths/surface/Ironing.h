#pragma once
// Ironing (ironing_enabled): the nozzle passes once more over a mesh's top surfaces with a trickle
// of material, as CuraEngine 4.13 irons (TopSurface):
//   where   — the top surface of layer i is the mesh's outline on i less its outline on i+1 (all of it
//             on the mesh's last layer); every layer is ironed, or with ironing_only_highest_layer
//             only the mesh's highest layer with an outline;
//   lines   — ironing_pattern at ironing_line_spacing, anchored at the plate's origin:
//               lines      — lines at the top skin's angle + 90° inside the surface shrunk by
//                            ironing_inset (the angle is roofing_angles[i] when roofing_layer_count
//                            and top_layers are above 0, else skin_angles[i]; 45°/135° by default);
//               zigzag     — the same lines joined at their ends (toolpaths/infill/ZigZag.h), in the surface
//                            shrunk by ironing_inset − s·w/2 + f·w/2 + w/2 (s = layer_height /
//                            infill_sparse_thickness, f = ironing_flow, w the line width), so that the
//                            edge of an ironing line meets the edge of the outer wall;
//               concentric — loops, the first ironing_inset + f·w/2 inside the surface, then one
//                            ironing_line_spacing further in each until nothing is left;
//   style   — width skin_line_width (no initial-layer factor), flow ironing_flow alone, speed
//             speed_ironing with the first layers' slow-down (toolpaths/core/FeatureStyle.h), extruder
//             top_bottom_extruder_nr; Feature Ironing (;TYPE:SKIN), printed after everything else of
//             the mesh on the layer (toolpaths/MeshToolpaths.h);
//   order   — ironing_monotonic: the lines are kept in order across their direction, along
//             (−cos a, sin a) as CuraEngine's monotonic order (toolpaths/skin/MonotonicOrder.h; lowest
//             first), each printed from its end nearer the nozzle (ExtrusionPath::keep_order) — a
//             polyline whose ends lie more than a spacing apart across them (zigzag) from the end
//             further back (ExtrusionPath::fixed_start);
//             otherwise nearest first, as every other group.
#include <vector>

#include "geometry/Point.h"
#include "settings/Settings.h"
#include "toolpaths/core/ExtrusionPath.h"
#include "toolpaths/core/FeatureStyle.h"
#include "toolpaths/infill/InfillPatterns.h"

namespace mixengine {

struct IroningParams {
    InfillPattern pattern = InfillPattern::ZigZag;  ///< Lines, ZigZag or Concentric
    coord_um line_spacing_um = 100;
    coord_um inset_um =
        0;  ///< how far the lines' centres stay inside the surface (after the pattern's compensation)
    double angle_degrees = 135;
    bool monotonic = false;
    FeatureStyle style;
};

/// The part of `outline` with no `outline_above` over it.
Paths topSurface(const Paths& outline, const Paths& outline_above);

/// The ironing settings of a mesh on `layer` (its skin angle), with the inset compensated as above.
IroningParams ironingParams(const Settings& mesh, int layer);

/// Ironing paths over `surface`.
std::vector<ExtrusionPath> ironingPaths(const Paths& surface, const IroningParams& params);

}  // namespace mixengine
