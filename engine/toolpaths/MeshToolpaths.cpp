#include "toolpaths/MeshToolpaths.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "common/ParallelFor.h"
#include "geometry/PointQueries.h"
#include "geometry/PolygonOps.h"
#include "toolpaths/core/FeatureStyle.h"
#include "toolpaths/infill/InfillLayers.h"
#include "toolpaths/infill/InfillPatterns.h"
#include "toolpaths/infill/MeshInfill.h"
#include "toolpaths/skin/BridgeSkin.h"
#include "toolpaths/skin/Skin.h"
#include "toolpaths/skin/SkinPaths.h"
#include "toolpaths/surface/FuzzySkin.h"
#include "toolpaths/surface/Ironing.h"
#include "toolpaths/surface/Spiralize.h"
#include "toolpaths/walls/BridgeWalls.h"
#include "toolpaths/walls/OutlineGaps.h"
#include "toolpaths/walls/OutlineOffsets.h"
#include "toolpaths/walls/Seam.h"
#include "toolpaths/walls/SmallFeatures.h"
#include "toolpaths/walls/WallOverlap.h"
#include "toolpaths/walls/Walls.h"

namespace mixengine {
namespace {

int countOf(const Settings& s, Key<SettingUnit::Integer> key) {
    return static_cast<int>(std::clamp<long long>(s.integer(key), 0, 1'000'000));
}

/// angles[layer % n], or the defaults when the list is empty.
double angleFor(const Settings& s, Key<SettingUnit::RealList> key, int layer,
                const std::vector<double>& defaults) {
    std::vector<double> angles = s.realList(key);
    if (angles.empty())
        angles = defaults;
    return angles[static_cast<std::size_t>(layer) % angles.size()];
}

Box2 outlineBounds(const std::vector<SlicedLayer>& layers) {
    Box2 box{0, 0, 0, 0};
    bool any = false;
    for (const SlicedLayer& layer : layers) {
        if (layer.outlines.empty())
            continue;
        const Box2 b = boundsOf(layer.outlines);
        box = any ? Box2{std::min(box.left, b.left), std::min(box.top, b.top), std::max(box.right, b.right),
                         std::max(box.bottom, b.bottom)}
                  : b;
        any = true;
    }
    return box;
}

Point2 middleOf(const Box2& box) {
    return {(box.left + box.right) / 2, (box.top + box.bottom) / 2};
}

Point2 meshCentre(const std::vector<SlicedLayer>& layers) {
    return middleOf(outlineBounds(layers));
}

/// The skin's reference walls and the removal widths left over (toolpaths/skin/Skin.h).
struct SkinReferences {
    SkinReference top, bottom;
    int roofing_wall = -1;  ///< min(2, wall_line_count) with roofing, else −1 (none)
};

bool outerSurfacesWanted(const Settings& s) {
    return s.text(key::retraction_combing) == "no_outer_surfaces";
}

SkinReferences skinReferences(const Settings& s) {
    const int walls = countOf(s, key::wall_line_count);
    const coord_um w0 = s.lengthMicrons(key::wall_line_width_0), wx = s.lengthMicrons(key::wall_line_width_x);
    auto length = [&](Key<SettingUnit::Millimetres> key) { return s.lengthMicrons(key); };
    return {skinReference(length(key::top_skin_preshrink), walls, w0, wx),
            skinReference(length(key::bottom_skin_preshrink), walls, w0, wx),
            countOf(s, key::roofing_layer_count) > 0 || outerSurfacesWanted(s) ? std::min(2, walls) : -1};
}

/// initial_bottom_layers: below it a spiralized mesh prints as usual.
int spiralBottomLayers(const Settings& s) {
    return countOf(s, key::initial_bottom_layers);
}

/// fill_perimeter_gaps (not in spiralize mode).
bool fillsPerimeterGaps(const Settings& s) {
    return !(s.text(key::fill_perimeter_gaps) == "nowhere") && !s.boolean(key::magic_spiralize);
}

/// Whether the layer's print outline is its outer wall's (MeshLayerGroups::print_outline): as CuraEngine
/// 4.13, with support_enable, no fill_outline_gaps and walls on the layer.
bool outlinedByOuterWall(const Settings& s, const WallParams& p) {
    return s.boolean(key::support_enable) && !s.boolean(key::fill_outline_gaps) && p.wall_count > 0;
}

WallParams wallParams(const Settings& s, const MeshStyles& styles, const SkinReferences& refs, int layer) {
    WallParams p;
    p.top_reference = refs.top.wall;
    p.bottom_reference = refs.bottom.wall;
    p.roofing_reference = refs.roofing_wall;
    p.wall_count = countOf(s, key::wall_line_count);
    if (layer % 2 == 1 && s.boolean(key::alternate_extra_perimeter))
        ++p.wall_count;  // one wall more on every other layer
    if (layer % 2 == 1 && spiralizeOn(s) && layer < spiralBottomLayers(s))
        p.wall_count += 5;  // spiralize: a watertight bottom (toolpaths/surface/Spiralize.h)
    p.outer_width_um = styles.wall_0.width_um;
    p.inner_width_um = styles.wall_x.width_um;
    p.outer_inset_um = s.lengthMicrons(key::wall_0_inset);
    p.outer_speed_mm_s = styles.wall_0.speed_mm_s;
    p.inner_speed_mm_s = styles.wall_x.speed_mm_s;
    p.outer_flow = styles.wall_0.flow;
    p.inner_flow = styles.wall_x.flow;
    p.outer_extruder = styles.wall_0.extruder;
    p.inner_extruder = styles.wall_x.extruder;
    p.group_by_outline = s.boolean(key::optimize_wall_printing_order);
    p.perimeter_gaps = fillsPerimeterGaps(s);
    p.outline_gaps = s.boolean(key::fill_outline_gaps);
    p.filter_tiny_gaps = s.boolean(key::filter_out_tiny_gaps);
    p.outer_first = outerWallFirst(s, layer);
    p.simplify_resolution_um = s.lengthMicrons(key::meshfix_maximum_resolution);
    p.simplify_deviation_um = s.lengthMicrons(key::meshfix_maximum_deviation);
    return p;
}

/// travel_compensate_overlapping_walls_0_enabled / _x_enabled (toolpaths/walls/WallOverlap.h): less flow
/// where the outer walls (the inner walls, all levels together) run closer than their width to another
/// piece of them, wall_min_flow the least; as CuraEngine 4.13, the inner walls at 1 µm less than their
/// width, so that neighbouring walls, one width apart, do not count.
void compensateOverlaps(std::vector<ExtrusionPath>& walls, const Settings& s, const WallParams& p) {
    const double min_flow = s.ratio(key::wall_min_flow);
    if (s.boolean(key::travel_compensate_overlapping_walls_0_enabled))
        compensateWallOverlaps(walls, Feature::WallOuter, {p.outer_width_um, min_flow});
    if (s.boolean(key::travel_compensate_overlapping_walls_x_enabled))
        compensateWallOverlaps(walls, Feature::WallInner, {p.inner_width_um - 1, min_flow});
}

SkinParams skinParams(const Settings& s, const SkinReferences& refs) {
    SkinParams p;
    p.top_layers = countOf(s, key::top_layers);
    p.bottom_layers = countOf(s, key::bottom_layers);
    p.initial_bottom_layers = countOf(s, key::initial_bottom_layers);
    auto length = [&](Key<SettingUnit::Millimetres> key) { return s.lengthMicrons(key); };
    p.top_preshrink_um = refs.top.leftover_preshrink_um;
    p.bottom_preshrink_um = refs.bottom.leftover_preshrink_um;
    p.top_expand_um = length(key::top_skin_expand_distance);
    p.bottom_expand_um = length(key::bottom_skin_expand_distance);
    p.min_width_for_expansion_um = length(key::min_skin_width_for_expansion);
    p.roofing_layers = countOf(s, key::roofing_layer_count);
    p.min_infill_area_um2 = s.real(key::min_infill_area) * 1e6;
    p.small_gaps_heuristic = s.boolean(key::skin_no_small_gaps_heuristic);
    p.outer_surfaces = outerSurfacesWanted(s);
    p.infill_opening_um = s.lengthMicrons(key::infill_line_width);
    return p;
}

/// The style of the lines half a wall line wide that fill gaps (perimeter and outline gaps), by the
/// `extruder` key's train, CuraEngine's perimeter-gap style: skin speed, inner-wall flow. With
/// speed_equalize_flow_enabled the speed is multiplied, as CuraEngine 4.13 does, by skin_line_width over the
/// gap width in whole microns divided as integers (2 for equal wall and skin widths), before the first
/// layers' ramp.
FeatureStyle perimeterGapStyle(const Settings& s, int layer, Key<SettingUnit::Extruder> extruder) {
    FeatureStyle style = featureStyle(
        s, {key::wall_line_width_0, key::speed_topbottom, key::wall_x_material_flow, extruder}, layer);
    style.width_um = s.lengthMicrons(key::wall_line_width_0) / 2;
    if (s.boolean(key::speed_equalize_flow_enabled) && style.width_um > 0) {
        const coord_um factor = s.lengthMicrons(key::skin_line_width) / style.width_um;
        style.speed_mm_s = slowdownBlend(s, s.number(key::speed_topbottom) * double(factor),
                                         s.number(key::speed_print_layer_0), layer);
    }
    return style;
}

/// The perimeter gaps' style (fill_perimeter_gaps; none without it).
std::optional<FeatureStyle> gapStyle(const Settings& s, int layer) {
    if (!fillsPerimeterGaps(s))
        return std::nullopt;
    return perimeterGapStyle(s, layer, key::top_bottom_extruder_nr);
}

/// fill_outline_gaps: the lines filling layer `layer`'s outline gaps, as CuraEngine 4.13 prints them
/// (processOutlineGaps): at the skin angle, in the perimeter gaps' style, by the outer wall's extruder.
std::vector<ExtrusionPath> outlineGapPaths(const Paths& gaps, const Settings& s, const SkinPathParams& skin,
                                           int layer) {
    if (gaps.empty())
        return {};
    return outlineGapLines(gaps, skin.skin.angle_degrees,
                           perimeterGapStyle(s, layer, key::wall_0_extruder_nr));
}

SkinPathParams skinPathParams(const Settings& s, int layer, coord_um z, const MeshStyles& styles) {
    SkinPathParams p;
    p.outline_count = countOf(s, key::skin_outline_count);
    p.simplify_resolution_um = s.lengthMicrons(key::meshfix_maximum_resolution);
    p.simplify_deviation_um = s.lengthMicrons(key::meshfix_maximum_deviation);
    p.z_um = z;
    p.first_layer = layer == 0;
    const Key<SettingUnit::Text> pattern_key =
        layer == 0 ? key::top_bottom_pattern_0 : key::top_bottom_pattern;
    p.skin.pattern = infillPatternOf(s.text(pattern_key), std::string(pattern_key.name));
    p.skin.angle_degrees = angleFor(s, key::skin_angles, layer, {45, 135});
    p.skin.overlap_um = s.lengthMicrons(key::skin_overlap_mm);
    p.skin.style = styles.skin;
    p.skin.monotonic = s.boolean(key::skin_monotonic);
    p.roofing.pattern = infillPatternOf(s.text(key::roofing_pattern), "roofing_pattern");
    p.roofing.angle_degrees = angleFor(s, key::roofing_angles, layer, {45, 135});
    p.roofing.style = styles.roofing;
    p.roofing.feature = Feature::Roofing;
    p.roofing.monotonic = s.boolean(key::roofing_monotonic);
    p.skin.connect_polygons = p.roofing.connect_polygons = s.boolean(key::connect_skin_polygons);
    p.gap_style = gapStyle(s, layer);
    p.gap_angle_degrees = p.roofing.angle_degrees;  // as CuraEngine: perimeter gaps at the roofing angles
    return p;
}

/// The outlines after xy_offset / xy_offset_layer_0 and hole_xy_offset (toolpaths/walls/OutlineOffsets.h).
Paths adjustedOutlines(const Paths& outlines, const Settings& s, int layer) {
    auto length = [&](Key<SettingUnit::Millimetres> key) { return s.lengthMicrons(key); };
    const coord_um xy = length(layer == 0 ? key::xy_offset_layer_0 : key::xy_offset);
    const coord_um hole = length(key::hole_xy_offset);
    return xy == 0 && hole == 0 ? outlines : offsetOutlines(outlines, xy, hole);
}

/// As CuraEngine 4.13: the gaps between the walls, and between the innermost wall and the skin and
/// infill — the latter unless there is no infill, its overlap is negative, or concentric infill
/// would not line up with the walls (alternate_extra_perimeter, a wider first layer).
Paths perimeterGaps(const Paths& between_walls, const Paths& inner_area, const SkinAreas& areas,
                    const Settings& s, int layer) {
    const bool concentric = s.text(key::infill_pattern) == "concentric";
    const bool wider_first = layer == 0 && s.ratio(key::initial_layer_line_width_factor) > 1.0;
    const bool inner_gaps = s.lengthMicrons(key::infill_line_distance) > 0 &&
                            (s.lengthMicrons(key::infill_overlap_mm) >= 0) &&
                            !(concentric && (s.boolean(key::alternate_extra_perimeter) || wider_first));
    if (!inner_gaps || inner_area.empty())
        return between_walls;
    const double width = double(s.lengthMicrons(key::infill_line_width));
    const bool filter = s.boolean(key::filter_out_tiny_gaps);
    // The inner area is united (WallResult): no union before the offset; skin and infill are each
    // united, and most layers have only one of them.
    const Paths gaps = differenceWithoutSmallIslands(offsetMiter(inner_area, -15, Loops::United),
                                                     unionOfUnited(areas.skin, areas.infill),
                                                     filter ? 2 * width * width : 0);
    return unionOfUnited(between_walls, gaps);
}

/// Whether any of `paths` starts inside `part`.
bool anyStartsIn(const std::vector<ExtrusionPath>& paths, const Paths& part) {
    return std::any_of(paths.begin(), paths.end(), [&](const ExtrusionPath& path) {
        return !path.points.empty() && insideArea(part, path.points.front(), true);
    });
}

/// Whether the outer walls' loops are still the outer wall's centre region (Walls.h), a Clipper
/// result that needs no union (wall overlap compensation only splits their lines): not when fuzzy
/// skin moved their points (they may cross themselves), nor when they are not the region's.
bool wallLoopsUnited(const Settings& s) {
    return !s.boolean(key::magic_fuzzy_skin_enabled) && s.text(key::magic_mesh_surface_mode) == "normal" &&
           !spiralizeOn(s);
}

/// The region inside the centre lines of the closed outer walls that start inside `part`: those
/// loops, united unless `loops_united` (wallLoopsUnited), as CuraEngine's offset unites them.
Paths outerWallRegion(const Paths& part, const MeshLayerGroups& walls, bool loops_united) {
    Paths loops;
    for (const ExtrusionPath& path : walls.outer_walls) {
        if (path.closed && path.points.size() >= 3 && insideArea(part, path.points.front(), true))
            loops.push_back(path.points);
    }
    return loops_united || loops.empty() ? loops : unionOf(loops);
}

/// (The comb areas below are built from Clipper results only — parts, the outer wall regions, offsets,
/// differences — so their offsets take them as united: Loops::United, no union pass before each.)

/// `area` with the narrow pieces of `outline` that it leaves out (those of `outline` that an
/// opening by `distance_um` removes), as CuraEngine 4.13 fills in where a wall is missing.
Paths withNarrowPieces(const Paths& area, const Paths& outline, coord_um distance_um, coord_um grow_um) {
    const Paths missing =
        differenceOf(outline, offsetMiter(offsetMiter(outline, -(distance_um + 5), Loops::United),
                                          distance_um + 10, Loops::United));
    return offsetMiter(
        unionOf(offsetMiter(area, grow_um, Loops::United), offsetMiter(missing, grow_um, Loops::United)),
        -grow_um, Loops::United);
}

/// The outer boundary of one part's wall combing region, as CuraEngine 4.13's noskin comb
/// boundary: the outer wall's inner edge (a quarter of its width inside its centre line when the
/// part has no inner wall), the part's outline where that leaves out a narrow piece; the outline
/// when the part has no wall.
Paths wallCombOuter(const Paths& part, const MeshLayerGroups& walls, coord_um width_0_um, bool loops_united) {
    const Paths region = outerWallRegion(part, walls, loops_united);
    if (region.empty())
        return part;
    const bool inner = anyStartsIn(walls.inner_walls, part);
    const coord_um to_outline = inner ? width_0_um : width_0_um * 3 / 4;
    const Paths outer = offsetMiter(region, -(inner ? width_0_um / 2 : width_0_um / 4), Loops::United);
    if (outer.size() == part.size())
        return outer;
    return withNarrowPieces(outer, part, to_outline, to_outline / 2 + 10);
}

/// One part's area inside its second wall, as CuraEngine 4.13's innermost walls with two insets
/// (its comb boundary for "all" and no_outer_surfaces): the outer wall's centre line (the outline
/// where that wall is missing), moved in to the second wall's centre line where the part has an
/// inner wall, keeping the outer wall's area where the second wall does not fit.
Paths innermostWallsArea(const Paths& part, const MeshLayerGroups& walls, coord_um width_0_um,
                         coord_um width_x_um, bool loops_united) {
    Paths outer = outerWallRegion(part, walls, loops_united);
    if (outer.empty())
        return part;
    const coord_um half_0 = width_0_um / 2, half_x = width_x_um / 2;
    if (outer.size() != part.size())
        outer = withNarrowPieces(outer, part, half_0, half_0);
    if (!anyStartsIn(walls.inner_walls, part))
        return outer;
    const coord_um spacing = half_0 + half_x;
    const Paths second = offsetMiter(outer, -spacing, Loops::United);
    const Paths missing = differenceOf(
        outer, offsetMiter(offsetMiter(outer, -(spacing + 5), Loops::United), spacing + 10, Loops::United));
    if (missing.empty())
        return second;
    const Paths merged =
        unionOf(offsetMiter(second, 2 * half_x, Loops::United), offsetMiter(missing, half_0, Loops::United));
    return intersectAll(offsetMiter(merged, -std::min(half_0, half_x), Loops::United), outer);
}

/// Every part's innermostWallsArea.
Paths innermostWalls(const MeshLayerGroups& walls, const Settings& s) {
    Paths area;
    const coord_um width_0_um = s.lengthMicrons(key::wall_line_width_0);
    const coord_um width_x_um = s.lengthMicrons(key::wall_line_width_x);
    const bool united = wallLoopsUnited(s);
    for (const Paths& part : walls.parts) {
        const Paths piece = innermostWallsArea(part, walls, width_0_um, width_x_um, united);
        area.insert(area.end(), piece.begin(), piece.end());
    }
    return area;
}

/// CuraEngine 4.13's noskin comb boundary: per part the wall region (wallCombOuter less the area
/// 10 µm inside the innermost wall), and the sparse infill area.
Paths noSkinCombArea(const MeshLayerGroups& walls, const Paths& inner_area, const SkinAreas& areas,
                     const Settings& s) {
    Paths outer;
    const coord_um width_0_um = s.lengthMicrons(key::wall_line_width_0);
    const bool united = wallLoopsUnited(s);
    for (const Paths& part : walls.parts) {
        const Paths piece = wallCombOuter(part, walls, width_0_um, united);
        outer.insert(outer.end(), piece.begin(), piece.end());
    }
    return unionOfUnited(areas.infill, differenceOf(outer, offsetMiter(inner_area, -10, Loops::United)));
}

/// MeshLayerGroups::comb_area for the mesh's retraction_combing mode (none for "off"; the sliced
/// outlines less the skin for noskin, and none for "all", in magic_mesh_surface_mode "surface",
/// which has no parts). As CuraEngine 4.13: noskin is noSkinCombArea, "all" innermostWalls,
/// no_outer_surfaces innermostWalls less the skin with air directly above or below, infill the
/// sparse infill area.
std::optional<Paths> combAreaFor(const Paths& outlines, const MeshLayerGroups& walls, const Paths& inner_area,
                                 const SkinAreas& areas, const Settings& s) {
    const std::string mode = s.text(key::retraction_combing);
    if (mode == "noskin")
        return walls.parts.empty() ? differenceOf(outlines, areas.skin)
                                   : noSkinCombArea(walls, inner_area, areas, s);
    if (mode == "no_outer_surfaces")
        return differenceOf(walls.parts.empty() ? outlines : innermostWalls(walls, s), areas.outer_surfaces);
    if (mode == "all" && !walls.parts.empty())
        return innermostWalls(walls, s);
    if (mode == "infill")
        return areas.infill;
    return std::nullopt;
}

/// magic_mesh_surface_mode "surface" (as CuraEngine 4.13): every loop of the outline, and every open
/// piece of an unclosed mesh, printed once along itself as outer wall; no other walls, skin or infill.
std::vector<MeshLayerGroups> surfaceToolpaths(const std::vector<SlicedLayer>& layers,
                                              const Settings& settings, const SeamParams& seam, int threads) {
    std::vector<MeshLayerGroups> result(layers.size());
    parallelFor(layers.size(), threads, [&](std::size_t i) {
        const int layer = static_cast<int>(i);
        const FeatureStyle style = meshStyles(settings, layer).wall_0;
        std::vector<ExtrusionPath>& walls = result[i].outer_walls;
        appendStyledLoops(adjustedOutlines(layers[i].outlines, settings, layer), Feature::WallOuter, style,
                          walls);
        applyFuzzySkin(walls, fuzzySkinParams(settings, layer), layer);
        placeSeams(walls, seam, layer);
        for (const Path& piece : layers[i].open_polylines) {
            if (piece.size() >= 2)
                walls.push_back(styledPath(piece, false, Feature::WallOuter, style));
        }
    });
    return result;
}

bool surfaceOnly(const Settings& s) {
    return s.text(key::magic_mesh_surface_mode) == "surface";
}

/// The mesh's highest layer with an outline (−1: none).
int highestFilledLayer(const std::vector<SlicedLayer>& layers) {
    for (std::size_t i = layers.size(); i-- > 0;) {
        if (!layers[i].outlines.empty())
            return static_cast<int>(i);
    }
    return -1;
}

/// The ironing of layer `i` (toolpaths/surface/Ironing.h); none unless ironing_enabled.
std::vector<ExtrusionPath> ironing(const std::vector<SlicedLayer>& layers, const Settings& s, std::size_t i) {
    if (!s.boolean(key::ironing_enabled))
        return {};
    const int layer = static_cast<int>(i);
    const bool only_highest = s.boolean(key::ironing_only_highest_layer);
    if (only_highest && layer != highestFilledLayer(layers))
        return {};
    const Paths above =
        i + 1 < layers.size() ? adjustedOutlines(layers[i + 1].outlines, s, layer + 1) : Paths{};
    const Paths outlines = adjustedOutlines(layers[i].outlines, s, layer);
    // Spiralized (as CuraEngine 4.13): the whole outline of the last bottom layer, nothing else.
    if (spiralizeOn(s) && layer + 1 != spiralBottomLayers(s))
        return {};
    const Paths surface = spiralizeOn(s) ? outlines : topSurface(outlines, above);
    return ironingPaths(surface, ironingParams(s, layer));
}

/// The spiral's wall loops made fuzzy, as CuraEngine 4.13 spirals the fuzzy outer wall
/// (toolpaths/surface/FuzzySkin.h; seeds apart from the walls').
Paths fuzzyLoops(Paths loops, const Settings& s, int layer) {
    const FuzzySkinParams fuzz = fuzzySkinParams(s, layer);
    if (!fuzz.enabled)
        return loops;
    for (std::size_t k = 0; k < loops.size(); ++k)
        loops[k] = fuzzyLoop(loops[k], fuzz, ~((std::uint64_t(std::uint32_t(layer)) << 32) | k));
    return loops;
}

/// Spiralize from initial_bottom_layers on: no skin, infill or perimeter gaps, and the spiral
/// (toolpaths/surface/Spiralize.h) with the outer walls.
void addSpirals(const std::vector<Paths>& spiral_loops, const Settings& s, const Point2& centre,
                std::vector<MeshLayerGroups>& result) {
    constexpr std::uint32_t kSpiralSequence = 0xFFFF'FFFFU;  // apart from the wall sequences
    std::vector<std::vector<ExtrusionPath>> spirals = spiralPaths(spiral_loops, s, centre, kSpiralSequence);
    for (std::size_t i = static_cast<std::size_t>(spiralBottomLayers(s)); i < result.size(); ++i) {
        result[i].skin.clear();
        result[i].infill.clear();
        for (ExtrusionPath& path : spirals[i])
            result[i].outer_walls.push_back(std::move(path));
    }
}

}  // namespace

bool outerWallFirst(const Settings& s, int layer) {
    return s.boolean(key::outer_inset_first) || (layer == 0 && s.text(key::adhesion_type) == "brim");
}

MeshAreas generateMeshAreas(const std::vector<SlicedLayer>& layers, const Settings& settings, int threads,
                            const WorkProgress& progress) {
    MeshAreas out;
    out.walls.resize(layers.size());
    out.inner_areas.resize(layers.size());
    out.wall_gaps.resize(layers.size());
    out.outline_gaps.resize(layers.size());
    std::vector<Paths> top_reference(layers.size()), bottom_reference(layers.size()),
        roofing_reference(layers.size());
    const SkinReferences refs = skinReferences(settings);
    const SeamParams seam = seamParamsFrom(settings, meshCentre(layers));
    const bool spiralize = spiralizeOn(settings);
    std::vector<Paths>& spiral_loops = out.spiral_loops;
    spiral_loops.resize(spiralize ? layers.size() : 0);
    const BridgeWallParams bridge_walls = bridgeWallParams(settings);
    parallelFor(layers.size(), threads, [&](std::size_t i) {
        const int layer = static_cast<int>(i);
        const Paths outlines = adjustedOutlines(layers[i].outlines, settings, layer);
        const WallParams params = wallParams(settings, meshStyles(settings, layer), refs, layer);
        WallResult walls = generateWalls(outlines, params);
        if (spiralize) {  // the first part's outer wall becomes the spiral (toolpaths/surface/Spiralize.h)
            SpiralParts parts = splitSpiralPart(outlines);
            spiral_loops[i] = fuzzyLoops(spiralWallLoops(parts.first, params), settings, layer);
            if (layer >= spiralBottomLayers(settings))
                walls.walls = generateWalls(parts.others, params).walls;
        }
        applyFuzzySkin(walls.walls, fuzzySkinParams(settings, layer), layer);
        slowSmallFeatures(walls.walls, smallFeatureParams(settings, layer));
        placeSeams(walls.walls, seam, layer);
        if (bridge_walls.enabled && layer > 0)
            markBridgedWalls(walls.walls, outlines,
                             adjustedOutlines(layers[i - 1].outlines, settings, layer - 1), bridge_walls);
        compensateOverlaps(walls.walls, settings, params);
        for (ExtrusionPath& path : walls.walls) {
            (path.feature == Feature::WallOuter ? out.walls[i].outer_walls : out.walls[i].inner_walls)
                .push_back(std::move(path));
        }
        out.walls[i].parts = std::move(walls.parts);
        if (outlinedByOuterWall(settings, params))
            out.walls[i].print_outline = offsetSquare(walls.outer_region, params.outer_width_um / 2);
        if (seam.type == SeamType::Back)
            out.walls[i].seam_position = seam.position_um;
        out.inner_areas[i] = std::move(walls.inner_area);
        top_reference[i] = std::move(walls.top_reference);
        bottom_reference[i] = std::move(walls.bottom_reference);
        roofing_reference[i] = std::move(walls.roofing_reference);
        out.wall_gaps[i] = std::move(walls.perimeter_gaps);
        out.outline_gaps[i] = std::move(walls.outline_gaps);
        progress.itemDone();
    });
    out.skin = computeSkinAreas(
        {&top_reference, &bottom_reference, refs.roofing_wall >= 0 ? &roofing_reference : nullptr},
        out.inner_areas, skinParams(settings, refs), threads);
    out.own_infill.resize(layers.size());
    for (std::size_t i = 0; i < layers.size(); ++i)
        out.own_infill[i] = out.skin[i].infill;
    return out;
}

namespace {

/// skin_edge_support_layers: the skin of that many layers above layer `i`, combined as CuraEngine
/// combines it (toolpaths/infill/MeshInfill.h); empty when the setting is 0.
Paths skinEdgeSupport(const std::vector<SkinAreas>& skin, std::size_t i, const Settings& s) {
    const std::size_t layers = static_cast<std::size_t>(countOf(s, key::skin_edge_support_layers));
    std::vector<const Paths*> above;
    for (std::size_t j = i + 1; j <= i + layers && j < skin.size(); ++j)
        above.push_back(&skin[j].skin);
    return above.empty() ? Paths{} : skinAboveForEdgeSupport(above);
}

}  // namespace

std::vector<MeshLayerGroups> generateMeshPaths(MeshAreas areas, const std::vector<SlicedLayer>& layers,
                                               const Settings& settings, int threads,
                                               const std::optional<Box2>& mesh_box_um,
                                               const WorkProgress& progress) {
    std::vector<MeshLayerGroups> result = std::move(areas.walls);
    result.resize(layers.size());
    const std::vector<LayerInfill> infill =
        arrangeInfill(areas.own_infill, infillLayerParams(settings), threads);
    const Box2 box = mesh_box_um ? *mesh_box_um : outlineBounds(layers);
    const Point2 middle = middleOf(box);
    const std::unique_ptr<SubdivCubes> cubes = meshSubdivCubes(layers, settings, middle, threads);
    const std::unique_ptr<CrossFill> cross = meshCrossFill(settings, box);
    const std::unique_ptr<LightningInfill> lightning = meshLightning(areas.own_infill, settings, threads);

    const BridgeSkinParams bridge = bridgeSkinParams(settings);
    std::vector<Paths> outlines, infill_areas;  // bridged skin: what lies below (the sparse infill as air)
    if (bridge.enabled) {
        for (std::size_t i = 0; i < layers.size(); ++i) {
            outlines.push_back(adjustedOutlines(layers[i].outlines, settings, static_cast<int>(i)));
            infill_areas.push_back(areas.skin[i].infill);
        }
    }

    parallelFor(layers.size(), threads, [&](std::size_t i) {
        const int layer = static_cast<int>(i);
        const coord_um z = layers[i].print_z;
        const SkinAreas& skin = areas.skin[i];
        const MeshStyles styles = meshStyles(settings, layer);
        SkinPathParams skin_params = skinPathParams(settings, layer, z, styles);
        if (bridge.enabled) {
            const LayersBelow below{&outlines, &infill_areas, layer};
            skin_params.bridge = [&bridge, below, &skin_params](const Paths& part) {
                return bridgeSkinFill(part, skin_params.skin, bridge, below);
            };
        }
        result[i].skin = outlineGapPaths(areas.outline_gaps[i], settings, skin_params, layer);
        for (ExtrusionPath& path : generateSkinPaths(skin.skin, skin.roofing, skin_params))
            result[i].skin.push_back(std::move(path));
        if (fillsPerimeterGaps(settings)) {
            for (ExtrusionPath& line : perimeterGapLines(
                     perimeterGaps(areas.wall_gaps[i], areas.inner_areas[i], skin, settings, layer),
                     skin_params))
                result[i].skin.push_back(std::move(line));
        }
        result[i].comb_area =
            combAreaFor(layers[i].outlines, result[i], areas.inner_areas[i], skin, settings);
        InfillParams fill = meshInfillParams(settings, layer, z, styles.infill, middle);
        const Paths subdiv_lines = cubes ? cubes->linesAt(z) : Paths{};
        fill.subdiv_lines = cubes ? &subdiv_lines : nullptr;
        fill.cross = cross.get();
        fill.lightning_trees = lightning ? &lightning->treesAt(i) : nullptr;
        SkinEdgeSupport edge{skinEdgeSupport(areas.skin, i, settings), {}};
        if (!edge.skin_above.empty())
            edge.parts = areas.inner_areas[i];
        result[i].infill = meshInfillPaths(infill[i], fill, edge);
        if (settings.boolean(key::infill_randomize_start_location))
            result[i].infill_start = randomInfillStart(result[i].infill, layer);
        result[i].ironing = ironing(layers, settings, i);
        progress.itemDone();
    });
    if (!areas.spiral_loops.empty())
        addSpirals(areas.spiral_loops, settings, meshCentre(layers), result);
    return result;
}

bool surfaceOnlyMesh(const Settings& settings) {
    return surfaceOnly(settings);
}

std::vector<MeshLayerGroups> generateMeshToolpaths(const std::vector<SlicedLayer>& layers,
                                                   const Settings& settings, int threads,
                                                   const std::optional<Box2>& mesh_box_um) {
    if (surfaceOnly(settings))
        return surfaceToolpaths(layers, settings, seamParamsFrom(settings, meshCentre(layers)), threads);
    const WorkProgress silent;
    return generateMeshPaths(generateMeshAreas(layers, settings, threads, silent), layers, settings, threads,
                             mesh_box_um, silent);
}

}  // namespace mixengine
