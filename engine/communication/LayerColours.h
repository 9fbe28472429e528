#pragma once
// `mixengine layers` on a mixing print (issue 26): what each layer prints, in the colour predicted to
// leave the nozzle. The plan's extrusions (PlanStep::Extrude with volume, after the mixing stage has
// set PlanStep::outlet_color: mixing/transition/OutletPrediction.h) become lines of their width in that
// colour, drawn over the layer's sliced outline, and layers.json gets, per layer, the colours used and the
// length printed in each.
//
// colouredLayers — every planned layer (;LAYER: number, raft layers negative) with its extrusions
//   joined into runs (consecutive extrusions of one colour and width, end to start) and the length
//   in each colour, in the order the colours are first used on the layer. The head is followed
//   through travels, extrusions and head lifts, across layers; an extrusion before the first known
//   head position has no start and is left out (a plan always travels first).
// colouredLayerSvg — layerToSvg's drawing (slicing/SliceDump.h) with the outline filled light grey,
//   the runs over it (round caps and joins, their own width; <g class="extrusions">, one
//   <path stroke="#rrggbb" stroke-width="w"> per run), the outline's edge over them, and a second
//   caption line with the ;LAYER: number, the colours and the length. The drawing grows to hold
//   lines outside the outline (brim, skirt, purge tower).
// colouredLayersToJson — layersToJson's document (its keys unchanged) with, per sliced layer,
//   "gcode_layer" (the ;LAYER: number that prints it, null when the toolpath stage dropped it as an
//   empty bottom layer) and "predicted_colors" ([{"color": "#rrggbb", "length_mm": 81.6}, …]), and
//   at the top "raft_layers": the raft's planned layers ({"gcode_layer": -3, "z_mm": 0.3,
//   "predicted_colors": […]}, bottom first), which no sliced layer stands for.
#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "planning/LayerPlan.h"
#include "slicing/SliceDump.h"

namespace mixengine {

using Rgb8 = std::array<std::uint8_t, 3>;

/// Consecutive extrusions of one colour and one width, each starting where the one before ended.
struct ColourRun {
    int color = -1;  ///< index into PrintPlan::outlet_colors
    coord_um width_um = 0;
    Path points;  ///< two or more (equal for an extrusion that does not move in XY)
};

struct ColouredLayer {
    int index = 0;   ///< ;LAYER: number (PlannedLayer::index)
    coord_um z = 0;  ///< nozzle height
    std::vector<ColourRun> runs;
    std::vector<std::pair<int, double>> lengths_mm;  ///< (colour, mm printed in it), first use first
};

std::vector<ColouredLayer> colouredLayers(const PrintPlan& plan);

/// "#rrggbb", lower case.
std::string colourHex(const Rgb8& rgb);

/// `printed` may be null (a sliced layer nothing prints: only the outline and the caption).
std::string colouredLayerSvg(const SlicedLayer& layer, const ColouredLayer* printed,
                             const std::vector<Rgb8>& colors, const SvgOptions& options = {});

/// `printed[i]`: the planned layer that prints sliced layer i (null: none); `raft`: the raft's layers.
std::string colouredLayersToJson(const std::vector<SlicedLayer>& layers,
                                 const std::vector<std::string>& mesh_names,
                                 const std::vector<const ColouredLayer*>& printed,
                                 const std::vector<const ColouredLayer*>& raft,
                                 const std::vector<Rgb8>& colors);

}  // namespace mixengine
