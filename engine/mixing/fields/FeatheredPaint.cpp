#include "mixing/fields/FeatheredPaint.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "mixing/chamber/ChamberModel.h"

namespace mixengine {
namespace {

constexpr double kMinStepUm = 500;
constexpr double kPrecisionUm = 4;  ///< the boundary's distance, to this (a 6 mm blend: 0.0007 of share)
constexpr int kMaxSteps = 60;
constexpr double kFar = 1e9;  ///< the gap where one of the two regions has no paint in reach

/// Steps across a blend zone between two mixes: each holds at most half the tolerance, and is at least
/// kMinStepUm wide.
int stepsBetween(const MixVector& a, const MixVector& b, double blend_um, double tolerance) {
    const double distance = shareDistance(a, b);
    const int by_tolerance =
        tolerance > 0 ? static_cast<int>(std::ceil(distance / (tolerance / 2) - 1e-9)) : 1;
    const int by_width = static_cast<int>(std::floor(blend_um / kMinStepUm + 1e-9));
    return std::max(1, std::min(by_tolerance, by_width));
}

std::array<double, 3> toArray(const Point3& p) {
    return {static_cast<double>(p.x), static_cast<double>(p.y), static_cast<double>(p.z)};
}

/// to − from, scaled to unit length; false when the two points (nearly) coincide.
bool unitDirection(const std::array<double, 3>& from, const std::array<double, 3>& to,
                   std::array<double, 3>& direction) {
    double length = 0;
    for (int k = 0; k < 3; ++k) {
        direction[k] = to[k] - from[k];
        length += direction[k] * direction[k];
    }
    length = std::sqrt(length);
    if (length < 1e-3)
        return false;
    for (double& d : direction)
        d /= length;
    return true;
}

}  // namespace

MixVector lerpMix(const MixVector& a, const MixVector& b, double w) {
    MixVector mix;
    mix.channels = std::max(a.channels, b.channels);
    for (int c = 0; c < kMaxMixChannels; ++c)
        mix[c] = a[c] + (b[c] - a[c]) * w;
    return mix;
}

FeatheredPaint::FeatheredPaint(const PaintedRegions& regions, std::vector<MixVector> region_mixes,
                               coord_um blend_um, double tolerance)
    : regions_(regions), region_mixes_(std::move(region_mixes)), blend_um_(static_cast<double>(blend_um)) {
    const int n = static_cast<int>(region_mixes_.size());
    mixes_ = region_mixes_;  // band r < n: region r's interior
    pairs_.resize(static_cast<std::size_t>(n) * static_cast<std::size_t>(n));
    for (int low = 0; low < n; ++low)
        for (int high = low + 1; high < n; ++high) {
            const MixVector& a = region_mixes_[static_cast<std::size_t>(low)];
            const MixVector& b = region_mixes_[static_cast<std::size_t>(high)];
            PairBands& pair = pairs_[static_cast<std::size_t>(low * n + high)];
            pair.first = bands();
            pair.steps = stepsBetween(a, b, blend_um_, tolerance);
            for (int j = 0; j < pair.steps; ++j)
                mixes_.push_back(lerpMix(a, b, (j + 0.5) / pair.steps));
        }
}

const FeatheredPaint::PairBands& FeatheredPaint::pairOf(int low, int high) const {
    const int n = static_cast<int>(region_mixes_.size());
    return pairs_[static_cast<std::size_t>(low * n + high)];
}

double FeatheredPaint::gapUm(const Ray& ray, double t) const {
    const std::array<double, 3> q = {ray.from[0] + t * ray.direction[0], ray.from[1] + t * ray.direction[1],
                                     ray.from[2] + t * ray.direction[2]};
    // the distances at the ray's start plus the way from it bound those at q (and skip far triangles)
    const std::array<double, 2> d =
        regions_.distancesToRegionsUm(q, ray.own, ray.other, {ray.own_um + t + 1, ray.other_um + t + 1});
    if (!std::isfinite(d[1]))
        return -kFar;  // no other paint near: on own's side
    return std::isfinite(d[0]) ? d[0] - d[1] : kFar;
}

double FeatheredPaint::crossingAlongUm(const Ray& ray, double limit_um) const {
    // The boundary on the ray: where the gap (own's distance − other's) turns from negative to ≥ 0, bracketed
    // to kPrecisionUm. False position, each point followed by a probe just across it (so a linear gap, as
    // from flat faces, is bracketed in two evaluations); a bisection whenever a step did not halve the
    // bracket (a gap that only touches zero, or a side without paint in reach).
    double lo = 0, hi = limit_um;
    double g_lo = ray.own_um - ray.other_um, g_hi = gapUm(ray, hi);
    if (g_lo >= 0)
        return 0;  // on the boundary already
    if (g_hi < 0)
        return limit_um;
    const auto narrow = [&](double t) {
        const double g = gapUm(ray, t);
        (g < 0 ? lo : hi) = t;
        (g < 0 ? g_lo : g_hi) = g;
        return g < 0;
    };
    bool bisect = false;
    for (int i = 0; i < kMaxSteps && hi - lo > kPrecisionUm; ++i) {
        const double width = hi - lo;
        if (bisect || g_lo <= -kFar || g_hi >= kFar) {
            narrow((lo + hi) / 2);
        } else {
            const double t = std::clamp(lo + width * (-g_lo) / (g_hi - g_lo), lo + kPrecisionUm / 4,
                                        hi - kPrecisionUm / 4);
            const double probe = narrow(t) ? t + kPrecisionUm / 2 : t - kPrecisionUm / 2;
            if (probe > lo && probe < hi)
                narrow(probe);
        }
        bisect = hi - lo > width / 2;
    }
    return (lo + hi) / 2;
}

double FeatheredPaint::boundaryDistanceUm(const Point3& p, const NearestRegions& nearest) const {
    Ray ray;
    ray.from = toArray(p);
    ray.own = nearest.own.region;
    ray.other = nearest.other.region;
    ray.own_um = nearest.own.distance_um;
    ray.other_um = nearest.other.distance_um;
    const double half_um = blend_um_ / 2;
    // across the boundary from a: the other region's point nearest a (not p's, which may be any of
    // several equally near)
    const double reach_um = regions_.reachUm();
    const NearestPaint across =
        regions_.nearestOf(ray.other, nearest.own.point_um.data(), reach_um * reach_um);
    if (across.region >= 0 && unitDirection(nearest.own.point_um, across.point_um, ray.direction)) {
        const double along = crossingAlongUm(ray, half_um);
        if (along < half_um)
            return along;
    }
    // a and b (nearly) coincide, or the boundary is not that way: towards b itself
    if (!unitDirection(ray.from, nearest.other.point_um, ray.direction))
        return 0;  // on the other region's painted surface: at the boundary
    return crossingAlongUm(ray, half_um);
}

FeatheredPaint::Place FeatheredPaint::placeOf(const Point3& p) const {
    const NearestRegions nearest = regions_.nearestRegions(p);
    Place place;
    place.own = nearest.own.region;
    const double half_um = blend_um_ / 2;
    if (place.own < 0 || nearest.other.region < 0 ||
        (nearest.other.distance_um - nearest.own.distance_um) / 2 >= half_um)
        return place;
    const double boundary_um = boundaryDistanceUm(p, nearest);
    if (boundary_um >= half_um)
        return place;
    place.low = std::min(place.own, nearest.other.region);
    place.high = std::max(place.own, nearest.other.region);
    place.along = (place.own == place.low ? half_um - boundary_um : half_um + boundary_um) / blend_um_;
    return place;
}

int FeatheredPaint::regionAt(const Point3& p) const {
    const Place place = placeOf(p);
    if (place.low < 0)
        return place.own;
    const PairBands& pair = pairOf(place.low, place.high);
    const int step = std::clamp(static_cast<int>(std::floor(place.along * pair.steps)), 0, pair.steps - 1);
    return pair.first + step;
}

std::optional<MixVector> FeatheredPaint::exactMixAt(const Point3& p) const {
    const Place place = placeOf(p);
    if (place.own < 0)
        return std::nullopt;
    if (place.low < 0)
        return region_mixes_[static_cast<std::size_t>(place.own)];
    return lerpMix(region_mixes_[static_cast<std::size_t>(place.low)],
                   region_mixes_[static_cast<std::size_t>(place.high)], place.along);
}

}  // namespace mixengine
