#include "toolpaths/SupportedSkinFan.h"

#include <algorithm>

#include "common/ParallelFor.h"
#include "geometry/Clip.h"
#include "geometry/PolygonOps.h"

namespace mixengine {
namespace {

bool isPlainSkin(const ExtrusionPath& path) {
    return path.feature == Feature::Skin && !path.bridge && path.points.size() >= 2;
}

/// Lines of a skin part: plain skin and its roofing (which CuraEngine prints without this fan).
bool isPartLine(const ExtrusionPath& path) {
    return isPlainSkin(path) || (path.feature == Feature::Roofing && !path.bridge && path.points.size() >= 2);
}

/// The skin parts of one layer: its plain skin lines grown by half their width, as islands.
std::vector<Paths> skinParts(const std::vector<ExtrusionPath>& skin) {
    Paths bands;
    for (const ExtrusionPath& path : skin) {
        if (!isPartLine(path))
            continue;
        Path line = path.points;
        if (path.closed)
            line.push_back(path.points.front());
        const Paths band =
            offsetMitred({line}, double(path.width_um) / 2 + 10, OffsetEnds::OpenSquare, 2.0, 25.0);
        bands.insert(bands.end(), band.begin(), band.end());
    }
    return bands.empty() ? std::vector<Paths>{} : splitIslands(unionOf(bands));
}

/// Whether `point` lies in the island (inside its outer contour).
bool inIsland(const Point2& point, const Paths& island) {
    for (const Path& loop : island) {
        if (counterClockwise(loop) && pointInLoop(point, loop) != 0)
            return true;
    }
    return false;
}

void markLayer(MeshLayerGroups& layer, const Paths& under, double fan_ratio) {
    const std::vector<Paths> parts = skinParts(layer.skin);
    for (const Paths& part : parts) {
        if (intersectAll(part, under).empty())
            continue;
        for (ExtrusionPath& path : layer.skin) {
            if (isPlainSkin(path) && inIsland(path.points.front(), part))
                path.fan_ratio = fan_ratio;
        }
    }
}

}  // namespace

void markSupportedSkinFan(const Settings& global, const Settings& mesh,
                          const std::vector<SupportLayerAreas>& support, std::vector<MeshLayerGroups>& layers,
                          int threads) {
    if (!global.boolean(key::support_enable) || !mesh.boolean(key::support_fan_enable) || support.empty())
        return;
    const coord_um layer_height = std::max<coord_um>(1, global.lengthMicrons(key::layer_height));
    const coord_um top_distance = std::max<coord_um>(0, mesh.lengthMicrons(key::support_top_distance));
    const std::size_t below = static_cast<std::size_t>((top_distance + layer_height - 1) / layer_height) + 1;
    const double fan_ratio = std::clamp(mesh.ratio(key::support_supported_skin_fan_speed), 0.0, 1.0);
    parallelFor(layers.size(), threads, [&](std::size_t i) {
        if (i == 0 || i < below || i - below >= support.size() || layers[i].skin.empty())
            return;
        const SupportLayerAreas& s = support[i - below];
        const Paths& under = s.roof.empty() ? s.support : s.roof;
        if (!under.empty())
            markLayer(layers[i], under, fan_ratio);
    });
}

}  // namespace mixengine
