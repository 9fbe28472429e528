#include "toolpaths/support/SupportStairs.h"

#include <algorithm>
#include <cmath>

#include "common/ParallelFor.h"
#include "geometry/Angles.h"
#include "geometry/PolygonOps.h"

namespace mixengine {
namespace {

constexpr double kCuraMiterLimit = 1.2;
constexpr coord_um kEdgeUm = 10;

/// The band from `inner` inside the outlines to `outer` outside them.
Paths band(const Paths& outlines, coord_um inner, coord_um outer) {
    return differenceOf(offsetMiter(outlines, outer, kCuraMiterLimit),
                        offsetMiter(outlines, -inner, kCuraMiterLimit));
}

}  // namespace

std::vector<Paths> slopedAreas(const std::vector<Paths>& model, const StairParams& p,
                               coord_um layer_height_um, int threads) {
    std::vector<Paths> sloped(model.size());
    if (p.step_layers <= 1)
        return sloped;
    const double tangent = std::tan(radiansFromDegrees(std::clamp(p.min_slope_degrees, 0.01, 89.99)));
    const coord_um w = kEdgeUm + static_cast<coord_um>(double(layer_height_um) / tangent) / 2;
    parallelFor(model.size(), threads, [&](std::size_t i) {
        if (i == 0)
            return;
        const Paths meet = intersectAll(band(model[i - 1], w, kEdgeUm), band(model[i], kEdgeUm, w));
        sloped[i] = offsetMiter(offsetMiter(meet, -kEdgeUm, kCuraMiterLimit), kEdgeUm + w, kCuraMiterLimit);
    });
    const std::size_t step = static_cast<std::size_t>(p.step_layers);
    for (std::size_t i = 2; i < sloped.size(); ++i) {
        if (i % step != 1)
            sloped[i] = unionOf(sloped[i], sloped[i - 1]);
    }
    return sloped;
}

StairSteps::StairSteps(const std::vector<Paths>* model, const std::vector<Paths>* sloped, StairParams params)
    : model_(model), sloped_(sloped), p_(params) {}

Paths StairSteps::keptFree(std::size_t i) {
    const std::size_t gap = static_cast<std::size_t>(std::max(0, p_.bottom_gap_layers));
    if (i < gap || (gap == 0 && p_.step_layers <= 1))
        return {};
    const std::size_t bottom = i - gap;
    const Paths& bottom_outline = (*model_)[bottom];
    if (p_.step_layers <= 1)
        return bottom_outline;
    Paths kept = unionOf(stair_, bottom_outline);
    const std::size_t step = static_cast<std::size_t>(p_.step_layers);
    if (i % step == 0) {  // the next step down
        const Paths supporting = bottom >= 1 ? (*model_)[bottom - 1] : Paths{};
        const Paths allowed =
            intersectAll(offsetMiter(supporting, p_.step_width_um, kCuraMiterLimit), (*sloped_)[i]);
        const long long lowest = static_cast<long long>(bottom) - p_.step_layers + 1;
        stair_ = lowest >= 0 ? intersectAll((*model_)[static_cast<std::size_t>(lowest)], allowed) : allowed;
    }
    return kept;
}

}  // namespace mixengine
