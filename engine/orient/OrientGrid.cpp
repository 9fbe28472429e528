// Seed 000's latitude/longitude grid (orient/Orienter.h).
#include <algorithm>
#include <cmath>

#include "common/ParallelFor.h"
#include "orient/OrientContext.h"

namespace mixengine::orient {

void runGridMethod(OrientContext& context, OrientResult& result) {
    const auto start = std::chrono::steady_clock::now();
    const double step = context.options.grid_step_deg;
    const int n = std::max(1, static_cast<int>(std::lround(360.0 / step)));
    VMap map;
    map.step_deg = step;
    map.rows = map.columns = n;
    map.exact = context.exact;
    map.values.assign(static_cast<std::size_t>(n) * n, 0.0);
    context.ensureModel();  // for the estimates reported next to the exact values
    parallelFor(map.values.size(), context.threads, [&](std::size_t k) {
        const double lat = static_cast<double>(k / n) * step, lon = static_cast<double>(k % n) * step;
        map.values[k] = context.exactOrEstimate(offsetDirection(lat, lon, context.d_unit));
    });
    result.evaluations = map.values.size();
    // The first minimum in storage order (latitude outer); float noise below 1e-6 of the volume ties.
    const double lowest = *std::min_element(map.values.begin(), map.values.end());
    const double tie = 1e-6 * (result.volume_a_mm3 + result.volume_b_mm3);
    std::size_t first = 0;
    while (map.values[first] > lowest + tie)
        ++first;
    result.angles = {static_cast<double>(first / n) * step, static_cast<double>(first % n) * step};
    result.direction =
        offsetDirection(result.angles.latitude_deg, result.angles.longitude_deg, context.d_unit);
    result.spin_deg = 0;
    result.rotation = seedRotation(result.angles.latitude_deg, result.angles.longitude_deg);
    result.picked_by = "grid: first minimum in storage order (seed 000)";
    result.v_after_mm3 = map.values[first];
    result.v_after_estimate_mm3 = context.model->at(result.direction);
    result.map = std::move(map);
    result.time.search_s = secondsSince(start);
}

}  // namespace mixengine::orient
