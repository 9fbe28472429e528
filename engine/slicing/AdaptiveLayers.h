#pragma once
// Adaptive layer heights (adaptive_layer_height_enabled, _variation, _variation_step, _threshold) as
// CuraEngine 4.13 computes them.
//
// The heights allowed are layer_height + variation down to layer_height − variation in steps of
// variation_step (only positive ones). Layer 0 is layer_height_0 thick. Each next layer, from the
// current top z, tries the heights from the largest down: the faces of interest are those whose z
// range meets [z, z + h] (z + h/2 with slicing_tolerance middle); the flattest of them (the smallest
// angle between a face's normal and the vertical, horizontal faces not counting as flat) decides:
// h is taken when h / tan(angle) ≤ threshold (the step a layer leaves on that face is small enough),
// or h is the smallest height, or the height falls from the layer below by more than one step; a
// height more than one step above the layer below is skipped (unless it is the smallest). When none
// is taken, the height where the flattest face was found is used. Layers are added until no face is
// left above z (at least two layers).
//
// Every layer is cut at its top (as CuraEngine cuts adaptive layers; LayerZ::slice_z = print_z).
#include <vector>

#include "geometry/Point.h"
#include "mesh/Mesh.h"
#include "slicing/LayerHeights.h"

namespace mixengine {

/// One face's z range (µm) and its angle from the horizontal plane's normal (radians; π for a
/// horizontal face).
struct FaceSlope {
    coord_um min_z = 0;
    coord_um max_z = 0;
    double angle = 0;
};

/// The faces of a mesh as placed (z above the plate).
std::vector<FaceSlope> faceSlopes(const Mesh& mesh);

struct AdaptiveLayerParams {
    coord_um layer_height_um = 200;
    coord_um layer_height_0_um = 200;
    coord_um variation_um = 100;  ///< adaptive_layer_height_variation
    coord_um step_um = 10;        ///< adaptive_layer_height_variation_step
    coord_um threshold_um = 200;  ///< adaptive_layer_height_threshold
    bool middle = true;           ///< slicing_tolerance middle
};

/// The layers; throws InputError naming adaptive_layer_height_variation_step when it is not positive.
std::vector<LayerZ> adaptiveLayerHeights(const std::vector<FaceSlope>& faces,
                                         const AdaptiveLayerParams& params);

}  // namespace mixengine
