#include "orient/Interference.h"

#include <algorithm>

namespace mixengine::orient {
namespace {

constexpr int kRaySamples = 4;  ///< sub-rays per cell side (16 per cell column)

double share(const VoxelGrid& grid) {
    return grid.rays ? static_cast<double>(grid.inconsistent_rays) / static_cast<double>(grid.rays) : 0.0;
}

}  // namespace

InterferenceModel::InterferenceModel(const Mesh& a, const Mesh& b, double offset_mm, Measure measure,
                                     int resolution, int threads)
    : offset_mm_(offset_mm), measure_(measure) {
    const auto [a_min, a_max] = boundsMm(a);
    const auto [b_min, b_max] = boundsMm(b);
    if (measure == Measure::OwnPart) {
        // One grid per part, fitted to its own box: box-shaped parts are voxelised exactly.
        frame_a_ = frameCovering(a_min, a_max, resolution);
        frame_b_ = frameCovering(b_min, b_max, resolution);
    } else {
        const Vec3 lo{std::min(a_min.x, b_min.x), std::min(a_min.y, b_min.y), std::min(a_min.z, b_min.z)};
        const Vec3 hi{std::max(a_max.x, b_max.x), std::max(a_max.y, b_max.y), std::max(a_max.z, b_max.z)};
        frame_a_ = frame_b_ = frameCovering(lo, hi, resolution);
    }
    const VoxelGrid grid_a = voxelise(a, frame_a_, kRaySamples, threads);
    const VoxelGrid grid_b = voxelise(b, frame_b_, kRaySamples, threads);
    volume_a_ = grid_a.volumeMm3();
    volume_b_ = grid_b.volumeMm3();
    bad_a_ = share(grid_a);
    bad_b_ = share(grid_b);
    std::vector<CorrelationPair> pairs{{0, 0}, {1, 1}};
    if (measure == Measure::AllMaterial)
        pairs.push_back({1, 0});  // vol(B ∩ (A + v))
    std::vector<CorrelationField> fields = correlate({&grid_a, &grid_b}, pairs, offset_mm, threads);
    g_a_ = std::move(fields[0]);
    g_b_ = std::move(fields[1]);
    if (measure == Measure::AllMaterial)
        cross_ = std::move(fields[2]);
}

double InterferenceModel::at(const Vec3& u) const {
    const Vec3 v = u * offset_mm_;
    double sum = g_a_.at(v) + g_b_.at(v * -1.0);
    if (measure_ == Measure::AllMaterial)
        sum += 2.0 * cross_.at(v);  // vol(A ∩ (B − v)) = vol((A + v) ∩ B)
    return sum;
}

std::vector<ExactTerm> exactTerms(const ExactSolid& a, const ExactSolid& b, const Vec3& v_mm,
                                  Measure measure) {
    std::vector<ExactTerm> terms{{&a, &a, v_mm}, {&b, &b, v_mm * -1.0}};
    if (measure == Measure::AllMaterial) {
        terms.push_back({&b, &a, v_mm});         // vol(B ∩ (A + v))
        terms.push_back({&a, &b, v_mm * -1.0});  // vol(A ∩ (B − v))
    }
    return terms;
}

std::optional<double> exactInterference(const ExactSolid& a, const ExactSolid& b, const Vec3& v_mm,
                                        Measure measure) {
    double sum = 0;
    for (const ExactTerm& t : exactTerms(a, b, v_mm, measure)) {
        const auto value = t.first->intersectionVolumeMm3(*t.second, t.shift_mm);
        if (!value)
            return std::nullopt;
        sum += *value;
    }
    return sum;
}

}  // namespace mixengine::orient
