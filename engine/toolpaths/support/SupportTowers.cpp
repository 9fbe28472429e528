#include "toolpaths/support/SupportTowers.h"

#include <cmath>

#include "geometry/Clip.h"
#include "geometry/PointQueries.h"
#include "geometry/PolygonOps.h"

namespace mixengine {
namespace {

double outerAreaUm2(const Paths& island) {
    return island.empty() ? 0.0 : std::abs(signedAreaUm2(island.front()));
}

Point2 middleOf(const Paths& area) {
    const Box2 box = boundsOf(area);
    return {(box.left + box.right) / 2, (box.top + box.bottom) / 2};
}

/// The overhang points of layer `i` (i ≥ 1).
std::vector<Paths> pointsOfLayer(const std::vector<SlicedLayer>& layers, std::size_t i, double max_area_um2,
                                 coord_um inset_um, const Paths* blocker) {
    std::vector<Paths> points;
    for (const Paths& island : splitIslands(layers[i].outlines)) {
        if (outerAreaUm2(island) >= max_area_um2 || !intersectAll(island, layers[i - 1].outlines).empty())
            continue;
        Paths point = offsetPolygons(island, -inset_um);
        if (blocker != nullptr && !point.empty())
            point = differenceOf(point, *blocker);
        if (!point.empty())
            points.push_back(std::move(point));
    }
    return points;
}

}  // namespace

std::vector<std::vector<Paths>> detectOverhangPoints(const std::vector<SlicedLayer>& layers,
                                                     coord_um max_diameter_um, coord_um inset_um,
                                                     const std::vector<Paths>* blockers) {
    std::vector<std::vector<Paths>> points(layers.size());
    const double max_area_um2 = double(max_diameter_um) * double(max_diameter_um);
    for (std::size_t i = 1; i < layers.size() && max_diameter_um > 0; ++i) {
        const Paths* blocker = blockers != nullptr && i < blockers->size() ? &(*blockers)[i] : nullptr;
        points[i] = pointsOfLayer(layers, i, max_area_um2, inset_um, blocker);
    }
    return points;
}

void TowerRoofs::startAt(const std::vector<Paths>& points, const std::vector<Paths>& points_below) {
    Paths near_below;
    for (const Paths& below : points_below)
        near_below = unionOf(near_below, offsetPolygons(below, 2 * params_.max_supported_diameter_um));
    for (const Paths& point : points) {
        Paths roof = near_below.empty() ? point : differenceOf(point, near_below);
        if (!roof.empty())
            roofs_.push_back(std::move(roof));
    }
}

void TowerRoofs::startUnderSmallIslands(const Paths& support, const Paths& support_above,
                                        const Paths& model_below) {
    const double max_area_um2 =
        double(params_.max_supported_diameter_um) * double(params_.max_supported_diameter_um);
    for (Paths& island : splitIslands(support)) {
        const double area = areaUm2(island);
        if (area <= 0 || area >= max_area_um2)
            continue;
        const Point2 middle = middleOf(island);
        if (insideArea(support_above, middle, true) && !insideArea(model_below, middle, true))
            roofs_.push_back(std::move(island));
    }
}

void TowerRoofs::addTo(Paths& area) {
    const double full_area_um2 = double(params_.diameter_um) * double(params_.diameter_um);
    for (Paths& roof : roofs_) {
        area = unionOf(area, roof);
        roof = outerAreaUm2(roof) < full_area_um2 ? offsetMiter(roof, params_.roof_step_um) : Paths{};
    }
    std::erase_if(roofs_, [](const Paths& roof) { return roof.empty(); });
}

}  // namespace mixengine
