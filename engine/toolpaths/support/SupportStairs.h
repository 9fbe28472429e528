#pragma once
// Support resting on a slope of the model, stair-stepped as CuraEngine 4.13's moveUpFromModel does
// (support_bottom_stair_step_height / _width / _min_slope). Going down, support stops
// support_bottom_distance above the model (bottom_gap_layers); with steps step_layers =
// support_bottom_stair_step_height / layer_height + 1 layers high (more than one), every step_layers
// layers the next step is laid out: the model of the step's lowest layer, where it lies within
// support_bottom_stair_step_width of the model under the current bottom layer and on a slope, is
// kept free of support for the whole step, so the support ends in flat stairs rather than following
// the slope layer by layer.
//
// The slopes per layer (slopedAreas): where the edge of layer i − 1 (a band w inside it, 10 µm
// outside) meets the edge of layer i (10 µm inside, w outside), w = 10 µm + (layer_height /
// tan(support_bottom_stair_step_min_slope)) / 2, opened by 10 µm and grown by 10 µm + w; within each
// step (from layer 1, step_layers at a time) every layer after the step's first adds the one below.
#include <vector>

#include "geometry/Point.h"

namespace mixengine {

struct StairParams {
    int step_layers = 1;  ///< 1: no stairs (only the bottom distance)
    coord_um step_width_um = 5000;
    double min_slope_degrees = 10;
    int bottom_gap_layers = 1;
};

/// The sloped areas of every layer (see above); empty without stairs.
std::vector<Paths> slopedAreas(const std::vector<Paths>& model, const StairParams& p,
                               coord_um layer_height_um, int threads);

/// What support must leave free on each layer because of the model below, asked for every layer from
/// the top down.
class StairSteps {
  public:
    StairSteps(const std::vector<Paths>* model, const std::vector<Paths>* sloped, StairParams params);
    /// Layer i's area kept free (besides the model on layer i itself); call with i decreasing.
    Paths keptFree(std::size_t i);

  private:
    const std::vector<Paths>* model_;
    const std::vector<Paths>* sloped_;
    StairParams p_;
    Paths stair_;  ///< the current step's area
};

}  // namespace mixengine
