#pragma once
// Plain-data views of sliced layers for people and scripts (the CLI writes them to files).
//
// writeLayersJson — every layer with its heights and paths, coordinates in integer microns:
//   {"units": "um", "layer_count": N,
//    "layers": [{"index": 0, "print_z": 200, "slice_z": 100,
//                "outlines": [[[x, y], …], …],        // outer CCW, holes CW (as SlicedLayer)
//                "open_polylines": [[[x, y], …], …]}, …]}
// layerToSvg — one layer as a standalone SVG document in millimetres (y up as in the printer):
//   outlines filled with fill-rule evenodd so holes show, open polylines stroked in red, a scale
//   bar of a round length in mm and a caption with the heights. An empty layer gives a 10 mm frame.
#include <string>
#include <vector>

#include "slicing/Slicer.h"

namespace mixengine {

std::string writeLayersJson(const std::vector<SlicedLayer>& layers);

struct SvgOptions {
    double pixels_per_mm = 10.0;  ///< size of the drawing in the SVG's width/height attributes
    double margin_mm = 2.0;       ///< space around the geometry
    std::string caption;          ///< shown above the heights (e.g. the mesh or layer name)
};

std::string layerToSvg(const SlicedLayer& layer, const SvgOptions& options = {});

}  // namespace mixengine
