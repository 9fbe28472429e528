#pragma once
// Spiralize ("vase mode": magic_spiralize, smooth_spiralized_contours) as CuraEngine 4.13 prints it.
//
// Below initial_bottom_layers a layer prints as usual, with 5 walls more on every odd layer (a
// watertight bottom). From initial_bottom_layers on there is no skin and no infill, and the outer
// wall of a layer's first part is one open line that starts where the layer below ended and rises
// by one layer thickness over its length (ExtrusionPath::spiral); the layer's other parts print their
// walls as usual. On layer initial_bottom_layers the part's outer wall is first printed flat, from
// the spiral's start.
//
// Seams (spiralSeams): on the first layer with a spiral wall, the vertex nearest to the z seam
// position (z_seam_type back) or to (0, 0); on each layer above, the vertex nearest to the seam of
// the layer below — moved one vertex on when the vertex after it lies behind that seam (seen along
// the inward normal there) and the two seams are at least meshfix_maximum_resolution apart, so the
// spiral never runs backwards.
//
// The slice of one layer (spiralSlice) starts at the seam of the layer below (its own seam on the
// bottom layer, the layer == bottom_layers) and goes once round the layer's wall, ending on the
// layer's seam vertex. With `smooth` (smooth_spiralized_contours) each point but the last is moved
// from the nearest point of the wall below towards its own place in proportion to the length printed
// (where the wall below is within two line widths), except on the bottom layer; without it, a short
// line first joins the wall from the start. On the bottom layer the flow rises from 0.25 to 1 over the
// loop; on the top layer (the last spiral layer) the loop is followed, flat, by a second round whose
// flow falls with the length printed (in steps of 0.05) and which moves on without extruding once
// the flow is below 0.25, for up to 10 mm; the top layer's speed is lowered so that the longer layer
// is not printed faster than the one below by the minimum layer time.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "geometry/Point.h"
#include "settings/Settings.h"
#include "toolpaths/core/ExtrusionPath.h"
#include "toolpaths/core/FeatureStyle.h"
#include "toolpaths/walls/Walls.h"

namespace mixengine {

/// The seam vertex of every layer's spiral wall (`walls[i]` empty = the layer has none; its entry is
/// then 0). `first_hint_um`: the z seam position, or (0, 0).
std::vector<std::size_t> spiralSeams(const std::vector<Path>& walls, const Point2& first_hint_um,
                                     coord_um max_resolution_um);

struct SpiralSliceParams {
    bool bottom = false;          ///< the layer numbered bottom_layers: the flow rises from 0.25
    bool top = false;             ///< the last layer with a spiral wall: the tapering second round
    bool smooth = false;          ///< smooth_spiralized_contours
    FeatureStyle style;           ///< the outer wall's
    double min_layer_time_s = 0;  ///< cool_min_layer_time (the top layer's speed)
};

/// The wall below the spiral of a layer: its loop and seam; none on the first spiral layer.
struct SpiralBelow {
    const Path* wall = nullptr;
    std::size_t seam = 0;
};

/// One layer's spiral: one path with a fixed start, the rising line and on the top layer the flat
/// tapering round after it (ExtrusionPath::spiral_flat_tail); empty for a wall of no length.
std::vector<ExtrusionPath> spiralSlice(const Path& wall, std::size_t seam, const SpiralBelow& below,
                                       const SpiralSliceParams& params);

/// magic_spiralize of the mesh group (the mesh's settings carry it).
bool spiralizeOn(const Settings& s);

/// The part of a layer the spiral follows: CuraEngine's first part (the first island as Clipper's
/// tree lists them, geometry/PolygonOps.h splitIslands), and the others.
struct SpiralParts {
    Paths first;
    Paths others;
};
SpiralParts splitSpiralPart(const Paths& outlines);

/// The outer wall loops of a part (its outline walled once with `outer` as the wall style and inset,
/// toolpaths/walls/Walls.h): the contour first, then its holes; empty when the part is too thin.
Paths spiralWallLoops(const Paths& part, const WallParams& outer);

/// The spiral paths of a mesh, per layer (none below initial_bottom_layers), from each layer's
/// spiral wall loops (spiralWallLoops; empty = no spiral part): on initial_bottom_layers the flat
/// loops first, the contour starting at the spiral's seam, then the spiral — one sequence
/// (ExtrusionPath::sequence `sequence`), so they print one after the other. Uses
/// initial_bottom_layers, bottom_layers, smooth_spiralized_contours, z_seam_type / _x / _y /
/// _relative (`mesh_centre_um`), meshfix_maximum_resolution, cool_min_layer_time and the outer
/// wall's style per layer.
std::vector<std::vector<ExtrusionPath>> spiralPaths(const std::vector<Paths>& wall_loops, const Settings& s,
                                                    const Point2& mesh_centre_um, std::uint32_t sequence);

}  // namespace mixengine
