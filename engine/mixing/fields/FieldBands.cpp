#include "mixing/fields/FieldBands.h"

#include <algorithm>
#include <cmath>

#include "mixing/chamber/ChamberModel.h"
#include "mixing/fields/MixSchedule.h"

namespace mixengine {
namespace {

constexpr double kMinBandUm = 1000;

/// The largest change of share per unit of the stops' heights (∞-free: 0 when flat or a hard step).
double largestSlope(const std::vector<GradientStop>& stops) {
    double slope = 0;
    for (std::size_t i = 1; i < stops.size(); ++i) {
        const double dh = stops[i].height - stops[i - 1].height;
        if (dh > 0)
            slope = std::max(slope, shareDistance(stops[i].mix, stops[i - 1].mix) / dh);
    }
    return slope;
}

}  // namespace

FieldBands::FieldBands(const MeshMixing& mixing, const Mesh& mesh, double tolerance)
    : axis_(mixing.axis), stops_(mixing.stops) {
    const AABB3 box = mesh.bounds();
    if (axis_ == GradientAxis::Radial) {
        centre_ = {(box.min.x + box.max.x) / 2, (box.min.y + box.max.y) / 2};
        for (const Point3& v : mesh.vertices)
            extent_um_ = std::max(extent_um_, distanceUm(centre_, {v.x, v.y}));
    } else {
        const bool x = axis_ == GradientAxis::X;
        low_um_ = static_cast<double>(x ? box.min.x : box.min.y);
        extent_um_ = static_cast<double>(x ? box.max.x - box.min.x : box.max.y - box.min.y);
    }
    extent_um_ = std::max(extent_um_, 1.0);
    // stop heights → microns along the axis
    um_per_unit_ = mixing.unit == HeightUnit::Percent ? extent_um_ / 100.0 : 1000.0;
    const double slope = largestSlope(mixing.stops) / um_per_unit_;  // share per micron
    band_um_ = slope > 0 ? std::max(kMinBandUm, tolerance / 2 / slope) : extent_um_;
    const int count = std::max(1, static_cast<int>(std::ceil(extent_um_ / band_um_ - 1e-9)));
    for (int b = 0; b < count; ++b) {
        const double middle_um = std::min(extent_um_, (b + 0.5) * band_um_);
        mixes_.push_back(mixAtHeight(mixing.stops, middle_um / um_per_unit_));
    }
}

double FieldBands::coordinateMm(const Point3& p) const {
    if (axis_ == GradientAxis::Radial)
        return distanceUm(centre_, {p.x, p.y}) / 1000.0;
    return ((axis_ == GradientAxis::X ? static_cast<double>(p.x) : static_cast<double>(p.y)) - low_um_) /
           1000.0;
}

std::optional<MixVector> FieldBands::exactMixAt(const Point3& p) const {
    return mixAtHeight(stops_, coordinateMm(p) * 1000.0 / um_per_unit_);
}

int FieldBands::regionAt(const Point3& p) const {
    const double along_um = coordinateMm(p) * 1000.0;
    const int band = static_cast<int>(std::floor(along_um / band_um_));
    return std::clamp(band, 0, bands() - 1);
}

}  // namespace mixengine
