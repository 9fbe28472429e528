#include "mesh/Mesh.h"

#include <algorithm>

namespace mixengine {

AABB3 Mesh::bounds() const {
    AABB3 box;
    for (const Point3& p : vertices) {
        box.min = {std::min(box.min.x, p.x), std::min(box.min.y, p.y), std::min(box.min.z, p.z)};
        box.max = {std::max(box.max.x, p.x), std::max(box.max.y, p.y), std::max(box.max.z, p.z)};
    }
    return box;
}

void Mesh::translate(coord_um dx, coord_um dy, coord_um dz) {
    for (Point3& p : vertices) {
        p.x += dx;
        p.y += dy;
        p.z += dz;
    }
}

}  // namespace mixengine
