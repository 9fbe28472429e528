#include "slicing/LayerHeights.h"

#include <algorithm>
#include <string>

#include "common/Error.h"

namespace mixengine {
namespace {

/// floor((model_max_z − layer_height_0) / layer_height) + 1, clamped to at least 1 (model_max_z > 0).
std::size_t layerCount(coord_um model_max_z, coord_um layer_height_0, coord_um layer_height) {
    const coord_um above_first = model_max_z - layer_height_0;
    if (above_first < 0)
        return 1;
    return static_cast<std::size_t>(above_first / layer_height) + 1;
}

}  // namespace

std::vector<LayerZ> computeLayerHeights(coord_um model_max_z, coord_um layer_height_0,
                                        coord_um layer_height) {
    if (layer_height_0 <= 0) {
        throw InputError("layer_height_0 must be positive, got " + std::to_string(layer_height_0) + " um");
    }
    if (layer_height <= 0) {
        throw InputError("layer_height must be positive, got " + std::to_string(layer_height) + " um");
    }
    if (model_max_z <= 0)
        return {};
    std::vector<LayerZ> layers(layerCount(model_max_z, layer_height_0, layer_height));
    layers[0] = {layer_height_0, 0, layer_height_0 / 2};
    for (std::size_t n = 1; n < layers.size(); ++n) {
        const coord_um print_z = layer_height_0 + static_cast<coord_um>(n) * layer_height;
        layers[n] = {print_z, print_z - layer_height, print_z - layer_height / 2};
    }
    return layers;
}

}  // namespace mixengine
