#include "toolpaths/surface/Mold.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/Clip.h"
#include "geometry/PolygonOps.h"

namespace mixengine {
namespace {

bool moldOn(const MoldMesh& m) {
    return m.settings->boolean(key::mold_enabled);
}

/// Open pieces as areas `width_um` wide (square ends), as CuraEngine thickens them for the mold.
Paths thickened(const Paths& lines, coord_um width_um) {
    if (lines.empty() || width_um <= 0)
        return {};
    return offsetMitred(lines, double(width_um) / 2.0, OffsetEnds::OpenSquare, 1.2, 10.0);
}

/// The model's outline on `layer` of mold mesh `m` (its open pieces are used up).
Paths modelOutline(const MoldMesh& m, std::size_t layer) {
    SlicedLayer& sliced = (*m.layers)[layer];
    double width = double(m.settings->lengthMicrons(key::wall_line_width_0));
    if (layer == 0)
        width *= m.settings->ratio(key::initial_layer_line_width_factor);
    Paths model = unionOf(sliced.outlines, thickened(sliced.open_polylines, static_cast<coord_um>(width)));
    sliced.open_polylines.clear();
    return model;
}

/// The mold of mesh `m` on `layer` from the model's outline and the mold's outline above.
Paths moldOutline(const MoldMesh& m, std::size_t layer, const Paths& model, const Paths& above,
                  coord_um layer_height_um) {
    const Settings& s = *m.settings;
    const coord_um width = s.lengthMicrons(key::mold_width);
    const double angle = s.angleDegrees(key::mold_angle);
    const auto inset =
        static_cast<coord_um>(std::tan(angle * std::numbers::pi / 180.0) * double(layer_height_um));
    Paths mold = offsetPolygons(model, width);
    if (angle < 90)
        mold = unionOf(offsetMiter(above, -inset), mold);
    const std::size_t roof_layers =
        layer_height_um > 0
            ? static_cast<std::size_t>(s.lengthMicrons(key::mold_roof_height) / layer_height_um)
            : 0;
    if (roof_layers > 0 && layer > 0) {
        const std::size_t below = layer > roof_layers ? layer - roof_layers : 0;
        mold = unionOf(mold, offsetPolygons((*m.layers)[below].outlines, width));
    }
    return mold;
}

}  // namespace

void applyMolds(const std::vector<MoldMesh>& meshes, coord_um layer_height_um) {
    if (std::none_of(meshes.begin(), meshes.end(), moldOn))
        return;
    std::size_t layer_count = 0;
    for (const MoldMesh& m : meshes)
        layer_count = std::max(layer_count, m.layers->size());
    std::vector<Paths> above(meshes.size());
    for (std::size_t layer = layer_count; layer-- > 0;) {
        Paths models;
        for (std::size_t k = 0; k < meshes.size(); ++k) {
            if (!moldOn(meshes[k]) || layer >= meshes[k].layers->size())
                continue;
            const Paths model = modelOutline(meshes[k], layer);
            models.insert(models.end(), model.begin(), model.end());
            above[k] = moldOutline(meshes[k], layer, model, above[k], layer_height_um);
            (*meshes[k].layers)[layer].outlines = above[k];
        }
        models = unionOf(models);
        for (const MoldMesh& m : meshes) {
            if (moldOn(m) && layer < m.layers->size())
                (*m.layers)[layer].outlines = differenceOf((*m.layers)[layer].outlines, models);
        }
    }
}

}  // namespace mixengine
