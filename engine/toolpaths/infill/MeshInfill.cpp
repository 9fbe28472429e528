#include "toolpaths/infill/MeshInfill.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "common/ParallelFor.h"
#include "geometry/PolygonOps.h"
#include "toolpaths/infill/cross/DensityImage.h"

namespace mixengine {
namespace {

/// CuraEngine's round_divide: a / b rounded half up (a ≥ 0, b > 0).
long long roundDivide(coord_um a, coord_um b) {
    return (a + b / 2) / b;
}

int countOf(const Settings& s, Key<SettingUnit::Integer> key) {
    return static_cast<int>(std::clamp<long long>(s.integer(key), 0, 1'000'000));
}

int combinedLayers(const Settings& s) {
    const coord_um layer_height = std::max<coord_um>(s.lengthMicrons(key::layer_height), 1);
    const coord_um thickness = s.lengthMicrons(key::infill_sparse_thickness);
    return static_cast<int>(
        std::clamp<long long>(roundDivide(std::max<coord_um>(thickness, 0), layer_height), 1, 1'000'000));
}

/// The densities' line distance and shift (see the header).
InfillParams densityParams(const InfillParams& base, std::size_t k, std::size_t last) {
    InfillParams p = base;
    const coord_um spread = base.line_distance_um << (k + 1);
    p.shift_um = spread / 2;
    p.line_distance_um = k == last ? spread / 2 : spread;
    return p;
}

double perimeterUm(const Paths& area) {
    double total = 0;
    for (const Path& path : area)
        total += lengthUm(path, true);
    return total;
}

void append(std::vector<ExtrusionPath>&& paths, std::vector<ExtrusionPath>& out) {
    out.insert(out.end(), std::make_move_iterator(paths.begin()), std::make_move_iterator(paths.end()));
}

/// Open lines of `paths` clipped to `tool`; loops are kept.
std::vector<ExtrusionPath> keepInside(std::vector<ExtrusionPath> paths, const Paths& tool) {
    std::vector<ExtrusionPath> out;
    for (ExtrusionPath& path : paths) {
        if (path.closed) {
            out.push_back(std::move(path));
            continue;
        }
        for (Path& piece : clipLines({path.points}, tool)) {
            ExtrusionPath part = path;
            part.points = std::move(piece);
            out.push_back(std::move(part));
        }
    }
    return out;
}

/// How far inside an area the lines of a denser infill stay: `walls` infill walls, and half a line
/// more (and 5 µm) when the lines are connected.
coord_um cutInset(const InfillParams& base, int walls) {
    const coord_um w = base.line_width_um;
    return walls * w + (base.connect_lines ? w / 2 + 5 : 0);
}

/// Without the loops (outer contours and holes alike) whose area is below `min_area_um2`.
Paths withoutSmallLoops(Paths area, double min_area_um2) {
    std::erase_if(area, [&](const Path& loop) { return std::abs(areaUm2({loop})) < min_area_um2; });
    return area;
}

/// The sparsest infill split along the skin of the layers above, in the parts where it is split.
struct SkinEdgeSplit {
    Paths below_skin;   ///< under the skin above
    Paths elsewhere;    ///< the rest of the sparsest area of those parts
    Paths filled;       ///< what of `elsewhere` gets infill (PartSplit::filled)
    Paths split_parts;  ///< the sparsest area of the parts split
};

/// One part's sparsest area split along the skin above.
struct PartSplit {
    Paths below;  ///< under the skin above
    Paths rest;   ///< the rest
    Paths filled;  ///< what of `rest` gets infill: without outer contours under 4 µm² per µm of its perimeter
};

/// The filter of an infill area before its infill is generated: without the islands (holes taken off)
/// under 4 µm² per µm of the area's perimeter. (CuraEngine 4.13 weighs each part's outer contours
/// without their holes against its own perimeter; this layer-wide filter is kept where no part is
/// split, the parts split get CuraEngine's: PartSplit::filled.)
Paths withoutSmallInfillIslands(const Paths& area) {
    return removeSmallIslands(area, 4.0 * perimeterUm(area));
}

/// One part's sparsest area `own` split as CuraEngine 4.13 partitions it for skin_edge_support_layers:
/// its part under `skin_above` (opened by a line width, without loops under 25 line widths squared) and
/// the rest (without outer contours under that, weighed without their holes: a thin ring round the
/// first stays); nothing when either is empty. As CuraEngine filters each part's rest before its
/// infill, outer contours are weighed without their holes there too (`filled`).
std::optional<PartSplit> splitPart(const Paths& own, const Paths& skin_above, coord_um w) {
    const double min_area_um2 = 25.0 * double(w) * double(w);
    Paths below = withoutSmallLoops(openPolygons(intersectAll(skin_above, own), w), min_area_um2);
    Paths rest = removeSmallOutlines(differenceOf(own, below), min_area_um2);
    constexpr coord_um kTinyUm = 20;  // CuraEngine: the skin/infill overlap is not enough
    if (rest.empty() || offsetMiter(below, -kTinyUm, Loops::United).empty())
        return std::nullopt;
    Paths filled = removeSmallOutlines(rest, 4.0 * perimeterUm(rest));
    return PartSplit{std::move(below), std::move(rest), std::move(filled)};
}

/// Whether `part` holds `island` (one of the islands of the layer's infill, which lie in the parts,
/// at most a few micrometres beyond them where the infill's opening rounded outwards). `boxes` are the
/// bounds of `parts`; index `k` names `part`.
bool partHolds(const std::vector<Box2>& boxes, std::size_t k, const Box2& island_box, const Paths& part,
               const Paths& island) {
    constexpr coord_um kReachUm = 10;
    auto near = [&](const Box2& a) {
        return a.left - kReachUm <= island_box.right && island_box.left - kReachUm <= a.right &&
               a.top - kReachUm <= island_box.bottom && island_box.top - kReachUm <= a.bottom;
    };
    if (!near(boxes[k]))
        return false;
    const auto candidates = std::count_if(boxes.begin(), boxes.end(), near);
    return candidates == 1 || !intersectAll(island, part).empty();
}

/// The layer's sparsest area `sparsest` part by part: the islands in each of `parts`, whole (as
/// CuraEngine 4.13 keeps each part's infill area as the opening of its inner area left it, not clipped
/// to that area).
std::vector<Paths> sparsestByPart(const Paths& sparsest, const std::vector<Paths>& parts) {
    std::vector<Box2> boxes;
    for (const Paths& part : parts)
        boxes.push_back(boundsOf(part));
    std::vector<Paths> own(parts.size());
    for (Paths& island : splitIslands(sparsest)) {
        const Box2 box = boundsOf(island);
        for (std::size_t k = 0; k < parts.size(); ++k) {
            if (partHolds(boxes, k, box, parts[k], island)) {
                own[k].insert(own[k].end(), island.begin(), island.end());
                break;
            }
        }
    }
    return own;
}

/// skin_edge_support_layers: `sparsest` split part by part (`parts`: the layer's parts; none: one
/// part); nothing when no part is split.
std::optional<SkinEdgeSplit> splitBySkinAbove(const Paths& sparsest, const Paths& skin_above,
                                              const Paths& parts, coord_um w) {
    if (skin_above.empty() || sparsest.empty())
        return std::nullopt;
    SkinEdgeSplit split;
    const std::vector<Paths> owns =
        parts.empty() ? std::vector<Paths>{sparsest} : sparsestByPart(sparsest, splitIslands(parts));
    for (const Paths& own : owns) {
        const std::optional<PartSplit> two = own.empty() ? std::nullopt : splitPart(own, skin_above, w);
        if (!two)
            continue;
        split.below_skin = unionOf(split.below_skin, two->below);
        split.elsewhere = unionOf(split.elsewhere, two->rest);
        split.filled = unionOf(split.filled, two->filled);
        split.split_parts = unionOf(split.split_parts, own);
    }
    if (split.below_skin.empty())
        return std::nullopt;
    return split;
}

/// The lines of density k (of `last`) in the infill under the skin above: at least one infill wall
/// on the sparsest; a denser one's lines kept inside those walls. As CuraEngine 4.13 prints them, the
/// lines (not the walls) come twice: its list of these lines is not emptied before the rest of the
/// infill is added to it, and both lists are printed.
void belowSkinInfill(const Paths& below_skin, const InfillParams& base, std::size_t k, std::size_t last,
                     std::vector<ExtrusionPath>& out) {
    const int walls = std::max(1, base.wall_count);
    InfillParams p = densityParams(base, k, last);
    p.multiplier = base.connect_lines && last != 0 ? 1 : base.multiplier;
    p.wall_count = k < last ? 0 : walls;
    p.area_loops = Loops::United;
    std::vector<ExtrusionPath> paths = generateInfill(below_skin, p);
    if (k < last)
        paths = keepInside(std::move(paths), offsetMiter(below_skin, -cutInset(base, walls)));
    for (const ExtrusionPath& path : paths) {
        if (!path.closed)
            out.push_back(path);
    }
    append(std::move(paths), out);
}

void singleLayer(const LayerInfill& layer, const InfillParams& base, const SkinEdgeSupport& edge,
                 std::vector<ExtrusionPath>& out) {
    const std::size_t last = layer.by_density.size() - 1;
    const std::optional<SkinEdgeSplit> split =
        splitBySkinAbove(layer.by_density[last][0], edge.skin_above, edge.parts, base.line_width_um);
    // As CuraEngine: in a part split, every density fills the whole rest. `filled`: the area that gets
    // infill (small islands gone), else the whole area.
    auto areaOf = [&](std::size_t k, bool filled) {
        const Paths& whole = layer.by_density[k][0];
        if (!split)
            return filled ? withoutSmallInfillIslands(whole) : whole;
        const Paths unsplit = differenceOf(whole, split->split_parts);
        return filled ? unionOf(withoutSmallInfillIslands(unsplit), split->filled)
                      : unionOf(unsplit, split->elsewhere);
    };
    const Paths sparsest = areaOf(last, false);
    for (std::size_t k = last + 1; k-- > 0;) {
        if (layer.by_density[k][0].empty())
            continue;
        if (split)
            belowSkinInfill(split->below_skin, base, k, last, out);
        InfillParams p = densityParams(base, k, last);
        p.multiplier = base.connect_lines && last != 0 ? 1 : base.multiplier;
        p.wall_count = k < last ? 0 : base.wall_count;
        p.area_loops = Loops::United;  // the islands of a union
        std::vector<ExtrusionPath> paths = generateInfill(areaOf(k, true), p);
        append(k < last
                   ? keepInside(std::move(paths), offsetMiter(sparsest, -cutInset(base, base.wall_count)))
                   : std::move(paths),
               out);
    }
}

void thickerLayers(const LayerInfill& layer, const InfillParams& base, std::vector<ExtrusionPath>& out) {
    const std::size_t last = layer.by_density.size() - 1;
    for (std::size_t t = 1; t < layer.by_density[0].size(); ++t) {
        for (std::size_t k = last + 1; k-- > 0;) {
            if (t >= layer.by_density[k].size() || layer.by_density[k][t].empty())
                continue;
            InfillParams p = densityParams(base, k, last);
            p.wall_count = 0;
            p.zigzag_ends = ZigzagEnds::Connected;
            p.flow = base.flow * double(t + 1);
            append(generateInfill(layer.by_density[k][t], p), out);
        }
    }
}

}  // namespace

InfillLayerParams infillLayerParams(const Settings& s) {
    InfillLayerParams p;
    const coord_um layer_height = std::max<coord_um>(s.lengthMicrons(key::layer_height), 1);
    p.support_only = s.boolean(key::infill_support_enabled);
    if (p.support_only) {
        const double angle = s.angleRadians(key::infill_support_angle);
        p.support_reach_um = static_cast<coord_um>((std::tan(angle) - 0.01) * double(layer_height));
    }
    p.gradual_steps = countOf(s, key::gradual_infill_steps);
    // At least one layer per step (CuraEngine would loop for ever on 0).
    p.gradual_step_layers = static_cast<int>(
        std::max<long long>(1, roundDivide(s.lengthMicrons(key::gradual_infill_step_height), layer_height)));
    p.small_gaps_heuristic = s.boolean(key::skin_no_small_gaps_heuristic);
    p.combine_layers = combinedLayers(s);
    p.initial_bottom_layers = countOf(s, key::initial_bottom_layers);
    p.top_layers = countOf(s, key::top_layers);
    return p;
}

InfillParams meshInfillParams(const Settings& s, int layer, coord_um z_um, const FeatureStyle& style,
                              const Point2& mesh_middle) {
    InfillParams p;
    p.line_distance_um = s.lengthMicrons(key::infill_line_distance);
    p.pattern = infillPatternOf(s.text(key::infill_pattern), "infill_pattern");
    const bool alternate = p.pattern == InfillPattern::Lines || p.pattern == InfillPattern::ZigZag;
    std::vector<double> angles = s.realList(key::infill_angles);
    if (angles.empty())
        angles = alternate ? std::vector<double>{45, 135} : std::vector<double>{45};
    p.angle_degrees = angles[static_cast<std::size_t>(layer / combinedLayers(s)) % angles.size()];
    p.z_um = z_um;
    p.line_width_um = style.width_um;
    p.speed_mm_s = style.speed_mm_s;
    p.flow = style.flow;
    p.extruder = style.extruder;
    p.origin_um = {mesh_middle.X + s.lengthMicrons(key::infill_offset_x),
                   mesh_middle.Y + s.lengthMicrons(key::infill_offset_y)};
    p.overlap_um = s.lengthMicrons(key::infill_overlap_mm);
    p.wall_count = countOf(s, key::infill_wall_line_count);
    p.multiplier = std::max(1, countOf(s, key::infill_multiplier));
    p.connect_lines = s.boolean(key::zig_zaggify_infill) || p.pattern == InfillPattern::ZigZag;
    p.pocket_um = s.lengthMicrons(key::cross_infill_pocket_size);
    p.simplify_resolution_um = s.lengthMicrons(key::meshfix_maximum_resolution);
    p.simplify_deviation_um = s.lengthMicrons(key::meshfix_maximum_deviation);
    p.connect_polygons = s.boolean(key::connect_infill_polygons);
    return p;
}

std::unique_ptr<CrossFill> meshCrossFill(const Settings& s, const Box2& mesh_box) {
    const std::string pattern = s.text(key::infill_pattern);
    const coord_um line_distance = s.lengthMicrons(key::infill_line_distance);
    const coord_um line_width = s.lengthMicrons(key::infill_line_width);
    if (!wantsCrossFill(pattern, line_distance, line_width))
        return nullptr;
    return std::make_unique<CrossFill>(
        mesh_box, line_distance, line_width,
        densityImageAt(s.text(key::cross_infill_density_image), mesh_box, "cross_infill_density_image"));
}

std::unique_ptr<SubdivCubes> meshSubdivCubes(const std::vector<SlicedLayer>& layers, const Settings& s,
                                             const Point2& mesh_middle, int threads) {
    if (s.text(key::infill_pattern) != "cubicsubdiv")
        return nullptr;
    SubdivCubeParams p;
    p.line_distance_um = s.lengthMicrons(key::infill_line_distance);
    if (p.line_distance_um <= 0)
        return nullptr;
    p.radius_addition_um = s.lengthMicrons(key::sub_div_rad_add);
    const std::vector<double> angles = s.realList(key::infill_angles);
    p.angle_degrees = angles.empty() ? 0.0 : angles.front();
    p.origin_um = {mesh_middle.X + s.lengthMicrons(key::infill_offset_x),
                   mesh_middle.Y + s.lengthMicrons(key::infill_offset_y)};
    p.layer_height_um = std::max<coord_um>(s.lengthMicrons(key::layer_height), 1);
    p.machine_size_um = {s.lengthMicrons(key::machine_width), s.lengthMicrons(key::machine_depth),
                         s.lengthMicrons(key::machine_height)};
    const int walls = countOf(s, key::wall_line_count);
    const coord_um w0 = s.lengthMicrons(key::wall_line_width_0), wx = s.lengthMicrons(key::wall_line_width_x);
    const coord_um inset = walls >= 2 ? w0 + wx / 2 : walls == 1 ? w0 / 2 : 0;
    std::vector<Paths> boundaries(layers.size());
    parallelFor(layers.size(), threads,
                [&](std::size_t i) { boundaries[i] = offsetMiter(layers[i].outlines, -inset); });
    return std::make_unique<SubdivCubes>(p, boundaries);
}

namespace {

/// layer_height · tan(angle), at most 10 m (a right angle reaches for ever).
coord_um reachOver(coord_um layer_height_um, double angle_radians) {
    const double reach = double(layer_height_um) * std::tan(angle_radians);
    return static_cast<coord_um>(std::clamp(reach, 0.0, 1e10));
}

}  // namespace

std::unique_ptr<LightningInfill> meshLightning(const std::vector<Paths>& infill_areas, const Settings& s,
                                               int threads) {
    const coord_um line_distance = s.lengthMicrons(key::infill_line_distance);
    if (s.text(key::infill_pattern) != "lightning" || line_distance <= 0)
        return nullptr;
    const coord_um width = s.lengthMicrons(key::infill_line_width);
    const coord_um layer_height = s.lengthMicrons(key::layer_height);
    LightningParams p;
    p.radius_um = std::max(line_distance, width) / 2;
    p.wall_reach_um = reachOver(layer_height, s.angleRadians(key::lightning_infill_overhang_angle));
    p.prune_um = reachOver(layer_height, s.angleRadians(key::lightning_infill_prune_angle));
    p.straighten_um = reachOver(layer_height, s.angleRadians(key::lightning_infill_straightening_angle));
    p.line_width_um = width;
    const coord_um inset = coord_um(countOf(s, key::infill_wall_line_count)) * width;
    std::vector<Paths> outlines(infill_areas.size());
    parallelFor(infill_areas.size(), threads, [&](std::size_t i) {
        outlines[i] = inset > 0 ? offsetMiter(infill_areas[i], -inset) : infill_areas[i];
    });
    return std::make_unique<LightningInfill>(p, outlines, threads);
}

std::vector<ExtrusionPath> meshInfillPaths(const LayerInfill& layer, const InfillParams& base,
                                           const SkinEdgeSupport& edge) {
    std::vector<ExtrusionPath> out;
    if (base.line_distance_um <= 0 || layer.by_density.empty())
        return out;
    thickerLayers(layer, base, out);
    singleLayer(layer, base, edge, out);
    return out;
}

Paths skinAboveForEdgeSupport(const std::vector<const Paths*>& skins) {
    constexpr coord_um kGapUm = 20;  // CuraEngine's tiny_infill_offset
    Paths combined;
    for (std::size_t i = skins.size(); i-- > 0;) {  // from the highest layer down
        for (const Paths& part : splitIslands(*skins[i])) {
            if (combined.empty()) {
                combined = part;
                continue;
            }
            const Paths overlap = intersectAll(combined, part);
            if (overlap.empty()) {
                combined = unionOf(combined, part);
            } else if (i > 0) {  // a layer above the next one: a small gap around the overlap
                const Paths grown = offsetMiter(overlap, kGapUm, Loops::United);
                combined =
                    unionOf(unionOf(differenceOf(combined, grown), differenceOf(part, grown)), overlap);
            } else {  // the layer right above: its skin whole, a small gap around it
                combined = unionOf(differenceOf(combined, offsetMiter(part, kGapUm, Loops::United)), part);
            }
        }
    }
    return combined;
}

std::optional<Point2> randomInfillStart(const std::vector<ExtrusionPath>& infill, int layer) {
    std::vector<const ExtrusionPath*> lines, loops;
    for (const ExtrusionPath& path : infill)
        (path.closed ? loops : lines).push_back(&path);
    std::minstd_rand random(static_cast<std::minstd_rand::result_type>(std::max(layer, 0)) + 1U);
    if (!lines.empty())
        return lines[random() % lines.size()]->points.front();
    if (loops.empty())
        return std::nullopt;
    const Path& loop = loops[random() % loops.size()]->points;
    return loop[random() % loop.size()];
}

}  // namespace mixengine
