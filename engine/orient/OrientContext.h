#pragma once
// Internal to orient/: what the sphere and grid methods share (orient/Orienter.h is the interface).
#include <chrono>
#include <memory>
#include <optional>

#include "orient/Orienter.h"

namespace mixengine::orient {

struct OrientContext {
    const Mesh& a;
    const Mesh& b;
    const OrientOptions& options;
    int threads = 1;
    Vec3 d_unit;
    double offset_mm = 0;
    std::unique_ptr<ExactSolid> solid_a, solid_b;
    bool exact = false;
    std::optional<InterferenceModel> model;  ///< built when the method or a fallback needs it

    /// V at direction u: exact when the solids allow it (falls back to the model if CGAL fails).
    double exactOrEstimate(const Vec3& u) const;
    /// Builds the model if it is not there yet.
    const InterferenceModel& ensureModel();
};

/// Fills the grid method's part of the result (angles, rotation, map, V after).
void runGridMethod(OrientContext& context, OrientResult& result);

/// Fills the V map from the model at `step_deg`.
VMap mapFromModel(const InterferenceModel& model, const Vec3& d_unit, double step_deg);

inline double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace mixengine::orient
