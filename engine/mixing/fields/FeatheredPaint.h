#pragma once
// Feathered paint (issue 27, mixing_paint_blend): the hard edge between two painted regions
// (mixing/fields/PaintedRegions.h) becomes a linear gradient `blend` wide. Within blend/2 of the boundary
// between regions R and S (the points as near R's painted triangles as S's) the asked mix goes linearly
// from R's solved mix to S's, the boundary itself asking for their 50/50 average; farther away a
// region keeps its own mix. Where a painted region meets unpainted surface (region −1, the object's
// own scheduled colour) the edge stays hard.
//
// As a gradient along an axis (mixing/fields/FieldBands.h), the blend is cut into bands that the splitter
// (mixing/fields/RegionSplit.h) and the transition planner see as regions: band r below the number of regions
// is region r's interior with its own mix; each pair of regions (every pair, whether or not the two
// meet) gets steps across its blend zone, a step holding a change of at most half the transition
// tolerance (share distance) and at least 0.5 mm wide, its mix the blend at the step's middle.
// exactMixAt gives the blend itself, for the planner that leads the chamber through continuous fields.
//
// The distance to the boundary: from p's nearest own triangle point a, the other region's point b′
// nearest a and p's nearest other-region point b, the boundary is searched (to 4 µm) along the ray from
// p in the direction a→b′ (exact for a painted face split by a straight edge, and for opposite faces),
// or where that ray does not reach it within blend/2, along p→b. (d_other − d_own) / 2, a lower bound
// of that distance, skips the search for points clearly outside the blend zone.
#include <optional>
#include <vector>

#include "mixing/fields/PaintedRegions.h"
#include "mixing/fields/RegionField.h"

namespace mixengine {

class FeatheredPaint : public RegionField {
  public:
    /// `regions`: the mesh's regions, built with the blend as extra reach; kept by reference (it must
    /// outlive this). `region_mixes[r]`: region r's solved mix. `blend_um` > 0; `tolerance`:
    /// mixing_transition_tolerance (share distance).
    FeatheredPaint(const PaintedRegions& regions, std::vector<MixVector> region_mixes, coord_um blend_um,
                   double tolerance);

    /// The band at `p` (microns, the mesh's frame); −1 where unpainted.
    int regionAt(const Point3& p) const override;
    /// The exact blend at `p`: a region's own mix outside the blend zones; empty where unpainted.
    std::optional<MixVector> exactMixAt(const Point3& p) const override;
    int bands() const { return static_cast<int>(mixes_.size()); }
    const MixVector& bandMix(int band) const { return mixes_[static_cast<std::size_t>(band)]; }
    double blendMm() const { return blend_um_ / 1000.0; }

    /// Where a point lies: its own region (−1: unpainted) and, inside a blend zone, the pair of regions
    /// (low < high) and how far along the zone it is (0 = low's edge of the zone, 1 = high's).
    struct Place {
        int own = -1;
        int low = -1, high = -1;  ///< −1: outside every blend zone
        double along = 0;
    };
    Place placeOf(const Point3& p) const;

  private:
    struct PairBands {
        int first = 0;  ///< band of the step at low's edge
        int steps = 1;
    };
    const PaintedRegions& regions_;
    std::vector<MixVector> region_mixes_;
    double blend_um_;
    std::vector<PairBands> pairs_;  ///< index low · regions + high
    std::vector<MixVector> mixes_;

    const PairBands& pairOf(int low, int high) const;
    double boundaryDistanceUm(const Point3& p, const NearestRegions& nearest) const;
    /// A ray searched for the boundary between `own` and `other`, and their distances at its start.
    struct Ray {
        std::array<double, 3> from{}, direction{};
        int own = -1, other = -1;
        double own_um = 0, other_um = 0;
    };
    double gapUm(const Ray& ray, double t) const;
    double crossingAlongUm(const Ray& ray, double limit_um) const;
};

/// The mix a + (b − a)·w, channel by channel.
MixVector lerpMix(const MixVector& a, const MixVector& b, double w);

}  // namespace mixengine
