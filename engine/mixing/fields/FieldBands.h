#pragma once
// Colour fields beyond Z (issue 27): a gradient along X, Y or radially (mixing_gradient_axis) cut
// into bands. A mixing chamber cannot follow a mix that changes along every wall loop, so each
// layer's extrusions are cut where they cross a band boundary (mixing/fields/RegionSplit.h) and every piece
// takes its band's mix — the field at the band's middle — and the transition planner
// (mixing/transition/TransitionPlan.h) prints the bands of a layer in the order of their mix, so the chamber
// steps one band at a time.
//
// The band width: the field's largest slope (share per unit of the axis, over its stops) makes a band
// as wide as a change of half the transition tolerance, so a band's own error is at most a quarter of
// the tolerance and neighbouring bands differ by half of it (the chamber follows such a step with
// little or no purge); never narrower than 1 mm.
//
// The coordinate along the axis is measured over the model as placed: x and y from its bounding box's
// low side, radial from its vertical centre axis (the middle of its bounding box) outward to its
// farthest vertex; in percent of that extent or in mm (mixing_gradient_unit).
#include <vector>

#include "mesh/Mesh.h"
#include "mixing/fields/RegionField.h"
#include "mixing/setup/MixingSettings.h"

namespace mixengine {

class FieldBands : public RegionField {
  public:
    /// `mixing`: a gradient with axis X, Y or Radial; `mesh` as placed (its frame = the plan's).
    FieldBands(const MeshMixing& mixing, const Mesh& mesh, double tolerance);

    int regionAt(const Point3& p) const override;
    /// The field itself at `p` (the stops at its coordinate), not rounded to a band.
    std::optional<MixVector> exactMixAt(const Point3& p) const override;
    int bands() const { return static_cast<int>(mixes_.size()); }
    const MixVector& bandMix(int band) const { return mixes_[static_cast<std::size_t>(band)]; }
    double bandWidthMm() const { return band_um_ / 1000.0; }
    /// The coordinate along the axis at `p`, in mm from the low side (or the centre axis).
    double coordinateMm(const Point3& p) const;

  private:
    GradientAxis axis_;
    double low_um_ = 0;     ///< x or y of the low side
    Point2 centre_{0, 0};   ///< radial: the vertical centre axis
    double extent_um_ = 0;  ///< the model's extent along the axis
    double band_um_ = 1000;
    double um_per_unit_ = 1000;  ///< the stops' unit (percent of the extent or mm) in microns
    std::vector<GradientStop> stops_;
    std::vector<MixVector> mixes_;
};

}  // namespace mixengine
