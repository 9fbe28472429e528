#include "toolpaths/support/TreeVolumes.h"

#include <algorithm>

#include "geometry/PolygonOps.h"

namespace mixengine {
namespace {

constexpr coord_um kSmoothUm = 5;  // the shrunk avoidance's tiny edges, every layer

}  // namespace

TreeVolumes::TreeVolumes(const std::vector<Paths>* model, TreeVolumeParams params)
    : model_(model), params_(params) {}

coord_um TreeVolumes::roundedRadius(coord_um radius_um) const {
    const coord_um step = std::max<coord_um>(1, params_.resolution_um);
    const coord_um r = std::max<coord_um>(0, radius_um);
    return (r + step - 1) / step * step;
}

Paths TreeVolumes::computeCollision(coord_um radius_um, int layer) const {
    const int n = static_cast<int>(model_->size());
    if (layer < 0 || layer >= n)
        return {};
    const Paths& here = (*model_)[static_cast<std::size_t>(layer)];
    if (here.empty())
        return {};
    if (!params_.z_overrides_xy)
        return offsetMiter(here, params_.xy_distance_um + radius_um);
    if (layer + params_.z_layers >= n)  // as CuraEngine: nothing collides on the top layers
        return {};
    const Paths& up = (*model_)[static_cast<std::size_t>(layer + params_.z_layers)];
    const Paths overhanging = offsetMiter(differenceOf(up, here), params_.xy_distance_um);
    Paths away = offsetMiter(here, params_.xy_distance_um);
    if (!overhanging.empty())
        away = differenceOf(away, overhanging);
    const Paths near = unionOf(away, offsetMiter(here, params_.xy_distance_overhang_um));
    return radius_um > 0 ? offsetMiter(near, radius_um) : near;
}

bool TreeVolumes::sizedForLayer(std::vector<Paths>& areas, std::vector<bool>& done, int layer) const {
    const std::size_t n = model_->size();
    if (areas.size() != n) {
        areas.assign(n, {});
        done.assign(n, false);
    }
    return layer >= 0 && static_cast<std::size_t>(layer) < n;
}

const Paths& TreeVolumes::collision(coord_um radius_um, int layer) {
    const coord_um r = roundedRadius(radius_um);
    std::vector<Paths>& areas = collision_[r];
    std::vector<bool>& done = collision_done_[r];
    static const Paths kNone;
    if (!sizedForLayer(areas, done, layer))
        return kNone;
    const std::size_t i = static_cast<std::size_t>(layer);
    if (!done[i]) {
        areas[i] = computeCollision(r, layer);
        done[i] = true;
    }
    return areas[i];
}

const Paths& TreeVolumes::avoidance(coord_um radius_um, int layer) {
    const coord_um r = roundedRadius(radius_um);
    std::vector<Paths>& areas = avoidance_[r];
    std::vector<bool>& done = avoidance_done_[r];
    static const Paths kNone;
    if (!sizedForLayer(areas, done, layer))
        return kNone;
    std::size_t first = static_cast<std::size_t>(layer);
    while (first > 0 && !done[first - 1])
        --first;
    for (std::size_t i = first; i <= static_cast<std::size_t>(layer); ++i) {
        if (done[i])
            continue;
        const Paths& own = collision(r, static_cast<int>(i));
        if (i == 0) {
            areas[i] = own;
        } else {
            const Paths shrunk = cleanPolygons(offsetMiter(areas[i - 1], -params_.max_move_um), kSmoothUm);
            areas[i] = unionOf(shrunk, own);
        }
        done[i] = true;
    }
    return areas[static_cast<std::size_t>(layer)];
}

}  // namespace mixengine
