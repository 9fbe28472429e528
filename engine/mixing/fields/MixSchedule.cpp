#include "mixing/fields/MixSchedule.h"

namespace mixengine {

MixVector mixAtHeight(const std::vector<GradientStop>& stops, double height) {
    if (height <= stops.front().height)
        return stops.front().mix;
    // The last stop strictly below `height`: the segment (below, next] holds it.
    std::size_t below = 0;
    while (below + 1 < stops.size() && stops[below + 1].height < height)
        ++below;
    if (below + 1 == stops.size())
        return stops.back().mix;
    const GradientStop& a = stops[below];
    const GradientStop& b = stops[below + 1];
    const double t = (height - a.height) / (b.height - a.height);  // b.height >= height > a.height
    MixVector mix = a.mix;
    for (int c = 0; c < kMaxMixChannels; ++c)
        mix[c] = a.mix[c] + (b.mix[c] - a.mix[c]) * t;
    return mix;
}

MixVector targetMix(const MeshMixing& mixing, double layer_top_mm, double mesh_height_mm) {
    if (mixing.mode == MixingMode::Dual || mixing.mode == MixingMode::Color)
        return mixing.fixed;
    double height = layer_top_mm;
    if (mixing.unit == HeightUnit::Percent)
        height = mesh_height_mm > 0 ? 100.0 * layer_top_mm / mesh_height_mm : 100.0;
    return mixAtHeight(mixing.stops, height);
}

}  // namespace mixengine
