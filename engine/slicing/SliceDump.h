#pragma once
// Plain-data views of sliced layers for people and scripts (`mixengine layers` writes them to files).
//
// layersToJson — the meshes' names and every layer with its heights, area and outlines, in mm:
//   {"meshes": ["cube20.stl", …],
//    "layers": [{"index": 0, "print_z_mm": 0.2, "slice_z_mm": 0.1, "area_mm2": 400.0,
//                "outlines": [[[x_mm, y_mm], …], …],   // outer CCW, holes CW (as SlicedLayer)
//                "open_polylines": 2}, …]}                // how many open pieces were left out
// area_mm2 is the signed area of the outlines (holes count negative). Keys are written sorted.
// layerToSvg — one layer as a standalone SVG document in millimetres (y up as in the printer):
//   outlines filled with fill-rule evenodd so holes show, open polylines stroked in red, a scale
//   bar of a round length in mm and a caption with the heights. An empty layer gives a 10 mm frame.
#include <sstream>
#include <string>
#include <vector>

#include "slicing/Slicer.h"

namespace mixengine {

std::string layersToJson(const std::vector<SlicedLayer>& layers, const std::vector<std::string>& mesh_names);

struct SvgOptions {
    double pixels_per_mm = 10.0;  ///< size of the drawing in the SVG's width/height attributes
    double margin_mm = 2.0;       ///< space around the geometry
    std::string caption;          ///< shown above the heights (e.g. the mesh or layer name)
};

std::string layerToSvg(const SlicedLayer& layer, const SvgOptions& options = {});

/// The parts of layerToSvg that other drawings share: a scale bar of 1, 2 or 5 × 10^k mm (about a fifth of
/// `width_mm`) at (x_mm, y_mm) with its label, and text made safe for XML (<, >, &, ").
void writeSvgScaleBar(std::ostringstream& svg, double x_mm, double y_mm, double width_mm, double stroke_mm);
std::string escapeXml(const std::string& text);

}  // namespace mixengine
