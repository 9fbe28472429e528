#include "slicing/LayerHeights.h"

#include <algorithm>
#include <string>

#include "common/Error.h"

namespace mixengine {
namespace {

/// The number of cutting planes at or below model_max_z, as CuraEngine 4.13 counts layers:
/// floor((model_max_z − layer_height_0 + layer_height / 2) / layer_height) + 1, computed in
/// half-microns so that it stays exact. (The simpler floor((z_max − h0) / h) + 1 drops a top layer
/// whose cutting plane still meets the model, e.g. 1070 instead of CuraEngine's 1071 layers on the
/// low-poly bunny.) Zero when even the first plane (layer_height_0 / 2) is above the model.
std::size_t layerCount(coord_um model_max_z, coord_um layer_height_0, coord_um layer_height) {
    if (2 * model_max_z < layer_height_0)
        return 0;
    const coord_um above = 2 * model_max_z - 2 * layer_height_0 + layer_height;
    if (above < 0)
        return 1;
    return static_cast<std::size_t>(above / (2 * layer_height)) + 1;
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
    const std::size_t count = model_max_z <= 0 ? 0 : layerCount(model_max_z, layer_height_0, layer_height);
    if (count == 0)
        return {};
    std::vector<LayerZ> layers(count);
    layers[0] = {layer_height_0, 0, layer_height_0 / 2};
    for (std::size_t n = 1; n < layers.size(); ++n) {
        const coord_um print_z = layer_height_0 + static_cast<coord_um>(n) * layer_height;
        layers[n] = {print_z, print_z - layer_height, print_z - layer_height / 2};
    }
    return layers;
}

}  // namespace mixengine
