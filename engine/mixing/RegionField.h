#pragma once
// Something that divides a model's volume into numbered regions, each printed in a mix of its own:
// painted regions (mixing/PaintedRegions.h) or the bands of a gradient along X, Y or radially
// (mixing/FieldBands.h). The extrusions of a model are cut where the region changes
// (mixing/RegionSplit.h).
#include "geometry/Point.h"

namespace mixengine {

class RegionField {
  public:
    virtual ~RegionField() = default;
    /// The region at `p` (microns, the mesh's frame), −1 for none.
    virtual int regionAt(const Point3& p) const = 0;
};

}  // namespace mixengine
