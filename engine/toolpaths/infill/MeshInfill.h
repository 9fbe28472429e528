#pragma once
// A mesh's sparse infill on one layer, from its arranged areas (toolpaths/infill/InfillLayers.h) and its
// settings (Cura's keys), as CuraEngine 4.13 prints it (FffGcodeWriter::process*LayerInfill):
//
//   pattern     — infill_pattern (toolpaths/infill/InfillPatterns.h) at infill_angles[(layer / N) % n]
//                 (default 45° and 135° for lines and zigzag, 45° otherwise; N the combined layer
//                 count of infill_sparse_thickness), reaching infill_overlap_mm beyond the area;
//   origin      — the mesh's middle (its bounding box's) moved by infill_offset_x / _y: the line
//                 sets pass through it;
//   density k   — of the layer's last (sparsest) density L: lines 2^(k+1)·d apart shifted by 2^k·d
//                 for k < L, 2^L·d apart for L, d = infill_line_distance; so where every density
//                 prints, the lines of all of them make spacing d. Lines of the denser areas stay
//                 inside the sparsest area (less the infill walls);
//   one layer   — the thickness-1 areas, each without its islands smaller than 4 µm² per µm of the
//                 area's perimeter; the sparsest gets infill_wall_line_count walls; the multiplier
//                 (infill_multiplier) is 1 when lines are connected and there are several densities;
//   thicker     — the areas printed t layers thick come first, with t × the flow, no walls, zigzag
//                 with its end pieces.
// zig_zaggify_infill (or the zigzag pattern) connects the lines.
#include <memory>
#include <optional>
#include <vector>

#include "geometry/Point.h"
#include "settings/Settings.h"
#include "slicing/Slicer.h"
#include "toolpaths/core/ExtrusionPath.h"
#include "toolpaths/core/FeatureStyle.h"
#include "toolpaths/infill/InfillLayers.h"
#include "toolpaths/infill/InfillPatterns.h"
#include "toolpaths/infill/SubdivCubes.h"
#include "toolpaths/infill/cross/CrossFill.h"
#include "toolpaths/infill/lightning/LightningInfill.h"

namespace mixengine {

/// The arrangement's parameters from the mesh's settings.
InfillLayerParams infillLayerParams(const Settings& s);

/// The pattern's parameters on `layer` at height z for density 0 of a single layer: line
/// distance infill_line_distance, the origin at `mesh_middle` + the infill offsets; for cross_3d the
/// pockets of cross_infill_pocket_size; cross's loops simplified by meshfix_maximum_resolution /
/// _deviation.
InfillParams meshInfillParams(const Settings& s, int layer, coord_um z_um, const FeatureStyle& style,
                              const Point2& mesh_middle);

/// cubicsubdiv's octree (toolpaths/infill/SubdivCubes.h) for a mesh whose infill_pattern is cubicsubdiv
/// (nothing otherwise): boundaries from its sliced layers' outlines, moved in to the centre line of
/// wall min(2, wall_line_count); origin as meshInfillParams'.
std::unique_ptr<SubdivCubes> meshSubdivCubes(const std::vector<SlicedLayer>& layers, const Settings& s,
                                             const Point2& mesh_middle, int threads);

/// The cross fractal (toolpaths/infill/cross/CrossFill.h) for a mesh whose infill_pattern is cross or
/// cross_3d and whose infill_line_distance is positive (nothing otherwise), over `mesh_box` (x, y) with
/// infill_line_width; the density from cross_infill_density_image when it names an existing image
/// (toolpaths/infill/cross/DensityImage.h), else uniform.
std::unique_ptr<CrossFill> meshCrossFill(const Settings& s, const Box2& mesh_box);
/// Lightning infill's trees (toolpaths/infill/lightning/LightningInfill.h) for a mesh whose
/// infill_pattern is lightning and whose infill_line_distance is above 0 (nothing otherwise):
/// `infill_areas[i]` is layer i's infill area (before it is split by density); the trees live in
/// it less infill_wall_line_count · infill_line_width; the angles' reaches are taken over
/// layer_height (at most 10 m).
std::unique_ptr<LightningInfill> meshLightning(const std::vector<Paths>& infill_areas, const Settings& s,
                                               int threads);
/// skin_edge_support_layers on one layer: the skin of the layers above (skinAboveForEdgeSupport; empty:
/// none) and the layer's parts (each island one part; empty: the whole layer one part).
struct SkinEdgeSupport {
    Paths skin_above;
    Paths parts;
};

/// The layer's infill paths: thicker areas first, then the single-layer ones from sparse to dense.
/// With `edge.skin_above`, as CuraEngine 4.13, the sparsest single-layer area of each part (its islands
/// of that area whole, not clipped to the part) is split along it — its piece under that skin (opened
/// by a line width, without loops under 25 line widths squared) gets at least one infill wall and
/// every density's lines of its own, printed twice as CuraEngine 4.13 prints them (its list of them is
/// not emptied before the rest is added), the rest (without outer contours under that size, each
/// weighed without its holes, so a thin ring round the piece stays) every density's lines; a part
/// where either piece would be empty is not split.
std::vector<ExtrusionPath> meshInfillPaths(const LayerInfill& layer, const InfillParams& base,
                                           const SkinEdgeSupport& edge = {});

/// The skin of the layers above combined as CuraEngine 4.13 does for skin_edge_support_layers:
/// `skins` are the skin areas of layers i+1 … i+n (nearest first); from the highest down each island
/// is added, where it overlaps what is there a 20 µm gap is kept around the overlap (around the whole
/// island for the nearest layer), so that terraced skin edges stay apart.
Paths skinAboveForEdgeSupport(const std::vector<const Paths*>& skins);

/// infill_randomize_start_location: the first point of an infill line picked at random (a
/// generator seeded with the layer number, as CuraEngine seeds rand() with it; a random vertex of
/// a loop when there are no lines); nothing without infill. The same on every run.
std::optional<Point2> randomInfillStart(const std::vector<ExtrusionPath>& infill, int layer);

}  // namespace mixengine
