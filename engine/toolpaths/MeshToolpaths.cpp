#include "toolpaths/MeshToolpaths.h"

#include <algorithm>

#include "common/ParallelFor.h"
#include "toolpaths/FeatureStyle.h"
#include "toolpaths/InfillLayers.h"
#include "toolpaths/InfillPatterns.h"
#include "toolpaths/Ironing.h"
#include "toolpaths/MeshInfill.h"
#include "toolpaths/OutlineOffsets.h"
#include "toolpaths/PolygonOps.h"
#include "toolpaths/Seam.h"
#include "toolpaths/Skin.h"
#include "toolpaths/SkinPaths.h"
#include "toolpaths/Walls.h"

namespace mixengine {
namespace {

int countOf(const Settings& s, std::string_view key, long long fallback = 0) {
    return static_cast<int>(std::clamp<long long>(s.has(key) ? s.integer(key) : fallback, 0, 1'000'000));
}

/// angles[layer % n], or the defaults when the list is empty.
double angleFor(const Settings& s, std::string_view key, int layer, const std::vector<double>& defaults) {
    std::vector<double> angles = s.has(key) ? s.realList(key) : std::vector<double>{};
    if (angles.empty())
        angles = defaults;
    return angles[static_cast<std::size_t>(layer) % angles.size()];
}

Point2 meshCentre(const std::vector<SlicedLayer>& layers) {
    ClipperLib::IntRect box{0, 0, 0, 0};
    bool any = false;
    for (const SlicedLayer& layer : layers) {
        if (layer.outlines.empty())
            continue;
        const ClipperLib::IntRect b = boundsOf(layer.outlines);
        box = any ? ClipperLib::IntRect{std::min(box.left, b.left), std::min(box.top, b.top),
                                        std::max(box.right, b.right), std::max(box.bottom, b.bottom)}
                  : b;
        any = true;
    }
    return {(box.left + box.right) / 2, (box.top + box.bottom) / 2};
}

/// The skin's reference walls and the removal widths left over (toolpaths/Skin.h).
struct SkinReferences {
    SkinReference top, bottom;
};

SkinReferences skinReferences(const Settings& s) {
    const int walls = countOf(s, "wall_line_count");
    const coord_um w0 = s.lengthMicrons("wall_line_width_0"), wx = s.lengthMicrons("wall_line_width_x");
    auto length = [&](std::string_view key) { return s.has(key) ? s.lengthMicrons(key) : coord_um{0}; };
    return {skinReference(length("top_skin_preshrink"), walls, w0, wx),
            skinReference(length("bottom_skin_preshrink"), walls, w0, wx)};
}

WallParams wallParams(const Settings& s, const MeshStyles& styles, const SkinReferences& refs, int layer) {
    WallParams p;
    p.top_reference = refs.top.wall;
    p.bottom_reference = refs.bottom.wall;
    p.wall_count = countOf(s, "wall_line_count");
    if (layer % 2 == 1 && s.has("alternate_extra_perimeter") && s.boolean("alternate_extra_perimeter"))
        ++p.wall_count;  // one wall more on every other layer
    p.outer_width_um = styles.wall_0.width_um;
    p.inner_width_um = styles.wall_x.width_um;
    p.outer_inset_um = s.has("wall_0_inset") ? s.lengthMicrons("wall_0_inset") : 0;
    p.outer_speed_mm_s = styles.wall_0.speed_mm_s;
    p.inner_speed_mm_s = styles.wall_x.speed_mm_s;
    p.outer_flow = styles.wall_0.flow;
    p.inner_flow = styles.wall_x.flow;
    p.outer_extruder = styles.wall_0.extruder;
    p.inner_extruder = styles.wall_x.extruder;
    return p;
}

SkinParams skinParams(const Settings& s, const SkinReferences& refs) {
    SkinParams p;
    p.top_layers = countOf(s, "top_layers");
    p.bottom_layers = countOf(s, "bottom_layers");
    p.initial_bottom_layers = countOf(s, "initial_bottom_layers", p.bottom_layers);
    auto length = [&](std::string_view key) { return s.has(key) ? s.lengthMicrons(key) : coord_um{0}; };
    p.top_preshrink_um = refs.top.leftover_preshrink_um;
    p.bottom_preshrink_um = refs.bottom.leftover_preshrink_um;
    p.top_expand_um = length("top_skin_expand_distance");
    p.bottom_expand_um = length("bottom_skin_expand_distance");
    p.min_width_for_expansion_um = length("min_skin_width_for_expansion");
    p.roofing_layers = countOf(s, "roofing_layer_count");
    p.min_infill_area_um2 = s.has("min_infill_area") ? s.real("min_infill_area") * 1e6 : 0.0;
    return p;
}

SkinFillParams skinFill(const Settings& s, int layer, coord_um z, const FeatureStyle& style, bool roofing) {
    SkinFillParams p;
    p.outline_count = countOf(s, "skin_outline_count");
    const char* pattern_key = roofing && s.has("roofing_pattern") ? "roofing_pattern"
                              : layer == 0                        ? "top_bottom_pattern_0"
                                                                  : "top_bottom_pattern";
    p.pattern = infillPatternOf(s.text(pattern_key), pattern_key);
    const double skin_angle = angleFor(s, "skin_angles", layer, {45, 135});
    p.angle_degrees = roofing ? angleFor(s, "roofing_angles", layer, {skin_angle}) : skin_angle;
    p.overlap_um = s.has("skin_overlap_mm") ? s.lengthMicrons("skin_overlap_mm") : 0;
    p.z_um = z;
    p.style = style;
    return p;
}

/// The outlines after xy_offset / xy_offset_layer_0 and hole_xy_offset (toolpaths/OutlineOffsets.h).
Paths adjustedOutlines(const Paths& outlines, const Settings& s, int layer) {
    auto length = [&](std::string_view key) { return s.has(key) ? s.lengthMicrons(key) : coord_um{0}; };
    const coord_um xy = length(layer == 0 ? "xy_offset_layer_0" : "xy_offset");
    const coord_um hole = length("hole_xy_offset");
    return xy == 0 && hole == 0 ? outlines : offsetOutlines(outlines, xy, hole);
}

/// The mesh's highest layer with an outline (−1: none).
int highestFilledLayer(const std::vector<SlicedLayer>& layers) {
    for (std::size_t i = layers.size(); i-- > 0;) {
        if (!layers[i].outlines.empty())
            return static_cast<int>(i);
    }
    return -1;
}

/// The ironing of layer `i` (toolpaths/Ironing.h); none unless ironing_enabled.
std::vector<ExtrusionPath> ironing(const std::vector<SlicedLayer>& layers, const Settings& s, std::size_t i) {
    if (!s.has("ironing_enabled") || !s.boolean("ironing_enabled"))
        return {};
    const int layer = static_cast<int>(i);
    const bool only_highest = s.has("ironing_only_highest_layer") && s.boolean("ironing_only_highest_layer");
    if (only_highest && layer != highestFilledLayer(layers))
        return {};
    const Paths above =
        i + 1 < layers.size() ? adjustedOutlines(layers[i + 1].outlines, s, layer + 1) : Paths{};
    const Paths surface = topSurface(adjustedOutlines(layers[i].outlines, s, layer), above);
    return ironingPaths(surface, ironingParams(s, layer));
}

}  // namespace

std::vector<MeshLayerGroups> generateMeshToolpaths(const std::vector<SlicedLayer>& layers,
                                                   const Settings& settings, int threads,
                                                   const std::optional<Point2>& mesh_middle_um) {
    std::vector<MeshLayerGroups> result(layers.size());
    std::vector<Paths> top_reference(layers.size()), bottom_reference(layers.size());
    const SkinReferences refs = skinReferences(settings);
    std::vector<Paths> inner_areas(layers.size());
    const SeamParams seam = seamParamsFrom(settings, meshCentre(layers));
    parallelFor(layers.size(), threads, [&](std::size_t i) {
        const int layer = static_cast<int>(i);
        WallResult walls = generateWalls(adjustedOutlines(layers[i].outlines, settings, layer),
                                         wallParams(settings, meshStyles(settings, layer), refs, layer));
        placeSeams(walls.walls, seam, layer);
        for (ExtrusionPath& path : walls.walls) {
            (path.feature == Feature::WallOuter ? result[i].outer_walls : result[i].inner_walls)
                .push_back(std::move(path));
        }
        inner_areas[i] = std::move(walls.inner_area);
        top_reference[i] = std::move(walls.top_reference);
        bottom_reference[i] = std::move(walls.bottom_reference);
    });

    const std::vector<SkinAreas> areas =
        computeSkinAreas(top_reference, bottom_reference, inner_areas, skinParams(settings, refs), threads);
    std::vector<Paths> infill_areas(layers.size());
    for (std::size_t i = 0; i < layers.size(); ++i)
        infill_areas[i] = areas[i].infill;
    const std::vector<LayerInfill> infill = arrangeInfill(infill_areas, infillLayerParams(settings), threads);
    const Point2 middle = mesh_middle_um ? *mesh_middle_um : meshCentre(layers);
    const std::unique_ptr<SubdivCubes> cubes = meshSubdivCubes(layers, settings, middle, threads);

    parallelFor(layers.size(), threads, [&](std::size_t i) {
        const int layer = static_cast<int>(i);
        const coord_um z = layers[i].print_z;
        const MeshStyles styles = meshStyles(settings, layer);
        result[i].skin = generateSkinPaths(areas[i].skin, skinFill(settings, layer, z, styles.skin, false));
        for (ExtrusionPath& path :
             generateSkinPaths(areas[i].roofing, skinFill(settings, layer, z, styles.roofing, true)))
            result[i].skin.push_back(std::move(path));
        InfillParams fill = meshInfillParams(settings, layer, z, styles.infill, middle);
        const Paths subdiv_lines = cubes ? cubes->linesAt(z) : Paths{};
        fill.subdiv_lines = cubes ? &subdiv_lines : nullptr;
        result[i].infill = meshInfillPaths(infill[i], fill);
        if (settings.has("infill_randomize_start_location") &&
            settings.boolean("infill_randomize_start_location"))
            result[i].infill_start = randomInfillStart(result[i].infill, layer);
        result[i].ironing = ironing(layers, settings, i);
    });
    return result;
}

}  // namespace mixengine
