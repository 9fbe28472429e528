#pragma once
// Something that divides a model's volume into numbered regions, each printed in a mix of its own:
// painted regions (mixing/fields/PaintedRegions.h) or the bands of a gradient along X, Y or radially
// (mixing/fields/FieldBands.h). The extrusions of a model are cut where the region changes
// (mixing/fields/RegionSplit.h).
#include <optional>

#include "geometry/Point.h"
#include "planning/MixVector.h"

namespace mixengine {

class RegionField {
  public:
    virtual ~RegionField() = default;
    /// The region at `p` (microns, the mesh's frame), −1 for none.
    virtual int regionAt(const Point3& p) const = 0;
    /// The mix asked for at `p` where the field changes continuously (a gradient, a feathered edge): its
    /// exact value, of which the region's mix is the band's approximation. Empty where the region's own
    /// mix is meant (hard-edged paint).
    virtual std::optional<MixVector> exactMixAt(const Point3& /*p*/) const { return std::nullopt; }
};

}  // namespace mixengine
