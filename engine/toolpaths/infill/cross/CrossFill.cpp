#include "toolpaths/infill/cross/CrossFill.h"

#include <algorithm>
#include <numbers>

#include "toolpaths/infill/cross/CrossCurve.h"
#include "toolpaths/infill/cross/SierpinskiSequence.h"

namespace mixengine {
namespace {

DensityAt uniform(coord_um line_distance_um, coord_um line_width_um) {
    const float density = float(line_width_um) / float(line_distance_um);
    return [density](const Box2&) { return density; };
}

}  // namespace

CrossSquare crossSquare(const Box2& model_box, coord_um line_distance_um) {
    const coord_um longer = std::max(model_box.right - model_box.left, model_box.bottom - model_box.top);
    int depth = 0;
    coord_um side = std::max<coord_um>(line_distance_um, 1);
    while (side < longer) {
        side *= 2;
        depth += 2;
    }
    const auto half_sqrt2 = static_cast<float>(0.5 * std::numbers::sqrt2);
    if (depth > 0 && float(side) * half_sqrt2 >= float(longer)) {
        side = static_cast<coord_um>(float(side) * half_sqrt2);
        --depth;
    }
    const Point2 middle{(model_box.left + model_box.right) / 2, (model_box.top + model_box.bottom) / 2};
    const coord_um radius = side / 2;
    return {{middle.X - radius, middle.Y - radius, middle.X + radius, middle.Y + radius}, depth};
}

CrossFill::CrossFill(const Box2& model_box, coord_um line_distance_um, coord_um line_width_um,
                     const DensityAt& density)
    : tree_([&] {
          const CrossSquare square = crossSquare(model_box, line_distance_um);
          return SierpinskiTree(square.square, square.depth, line_width_um,
                                density ? density : uniform(line_distance_um, line_width_um));
      }()) {
    sequence_ = crossSequence(tree_);
}

Path CrossFill::curve(bool three_d, coord_um z_um, coord_um line_width_um, coord_um pocket_um) const {
    if (!three_d)
        return crossCurve(tree_, sequence_);
    return cross3dCurve(tree_, sequence_, {z_um, line_width_um / 2, pocket_um});
}

}  // namespace mixengine
