#include "orient/Orienter.h"

#include <algorithm>
#include <cmath>

#include "common/Error.h"
#include "common/ParallelFor.h"
#include "orient/OrientContext.h"
#include "orient/SphereSearch.h"

namespace mixengine::orient {
namespace {

constexpr double kMapStepDeg = 2.0;  ///< the sphere method's V map (plot, report)

/// Exact evaluations of the sphere method: "before" (u = d̂) and the chosen candidates.
void verifyCandidates(OrientContext& context, OrientResult& result) {
    // Candidates whose estimate is within 1 % of the parts' volume of the best one: the voxel
    // estimate is that close (tests: ≤ 0.2 % on the corpus pairs), so the others cannot win.
    std::vector<std::size_t> chosen;
    double best = 1e300;
    for (const CandidateReport& c : result.candidates)
        best = std::min(best, c.v_estimate_mm3);
    const double slack = 0.01 * (result.volume_a_mm3 + result.volume_b_mm3) + 1.0;
    int minima = 0;
    for (std::size_t i = 0; i < result.candidates.size(); ++i) {
        const CandidateReport& c = result.candidates[i];
        const bool flat = c.source.starts_with("flat");
        if (context.options.verify <= 0 || c.v_estimate_mm3 > best + slack ||
            (!flat && minima >= context.options.verify))
            continue;
        chosen.push_back(i);
        minima += flat ? 0 : 1;
    }
    if (!context.exact || chosen.empty())
        return;  // nothing verified: the estimates compete
    // Every term of every evaluation is one task: "before" (u = d̂) first, then the candidates.
    std::vector<ExactTerm> terms;
    std::vector<std::size_t> owner;  // evaluation of each term
    for (std::size_t k = 0; k <= chosen.size(); ++k) {
        const Vec3 u = k == 0 ? context.d_unit : result.candidates[chosen[k - 1]].u;
        for (const ExactTerm& t :
             exactTerms(*context.solid_a, *context.solid_b, u * context.offset_mm, context.options.measure)) {
            terms.push_back(t);
            owner.push_back(k);
        }
    }
    std::vector<std::optional<double>> parts(terms.size());
    parallelFor(terms.size(), context.threads, [&](std::size_t i) {
        parts[i] = terms[i].first->intersectionVolumeMm3(*terms[i].second, terms[i].shift_mm);
    });
    std::vector<std::optional<double>> values(chosen.size() + 1, 0.0);
    for (std::size_t i = 0; i < terms.size(); ++i) {
        if (values[owner[i]] && parts[i])
            *values[owner[i]] += *parts[i];
        else
            values[owner[i]].reset();
    }
    if (values[0])
        result.v_before_mm3 = *values[0];
    for (std::size_t k = 0; k < chosen.size(); ++k)
        result.candidates[chosen[k]].v_exact_mm3 = values[k + 1];
}

/// The value a candidate competes with: exact when verified (or when nothing could be verified).
std::optional<double> competingValue(const CandidateReport& c, bool exact) {
    if (c.v_exact_mm3)
        return c.v_exact_mm3;
    if (!exact)
        return c.v_estimate_mm3;
    return std::nullopt;
}

void chooseSphereResult(OrientContext& context, OrientResult& result, const SurfaceSample& surface,
                        const std::vector<Vec3>& flats) {
    const auto start = std::chrono::steady_clock::now();
    const bool verified = std::any_of(result.candidates.begin(), result.candidates.end(),
                                      [](const CandidateReport& c) { return c.v_exact_mm3.has_value(); });
    result.exact = verified;
    double best = 1e300;
    for (const CandidateReport& c : result.candidates) {
        if (const auto v = competingValue(c, verified))
            best = std::min(best, *v);
    }
    const double tie = std::max(1.0, 1e-3 * (result.volume_a_mm3 + result.volume_b_mm3));
    std::vector<SpinOption> options;
    for (std::size_t i = 0; i < result.candidates.size(); ++i) {
        const auto v = competingValue(result.candidates[i], verified);
        if (!v || *v > best + tie)
            continue;
        for (const double spin : spinsToTry(result.candidates[i].angles, context.d_unit, flats))
            options.push_back({static_cast<int>(i), SpinScore{spin, 0, 0, 0}});
    }
    parallelFor(options.size(), context.threads, [&](std::size_t k) {
        const double spin = options[k].score.spin_deg;
        const LatLon& angles = result.candidates[static_cast<std::size_t>(options[k].candidate)].angles;
        options[k].score =
            surface.score(spunRotation(angles, context.d_unit, spin), context.options.overhang_angle_deg);
        options[k].score.spin_deg = spin;
    });
    const SpinOption pick = chooseOption(options, context.options.objective, result.picked_by);
    const CandidateReport& winner = result.candidates[static_cast<std::size_t>(pick.candidate)];
    result.direction = winner.u;
    result.angles = winner.angles;
    result.spin_deg = pick.score.spin_deg;
    result.score = pick.score;
    result.rotation = spunRotation(winner.angles, context.d_unit, pick.score.spin_deg);
    result.v_after_mm3 = *competingValue(winner, verified);
    result.v_after_estimate_mm3 = winner.v_estimate_mm3;
    result.time.spin_s = secondsSince(start);
}

void runSphereMethod(OrientContext& context, OrientResult& result) {
    const InterferenceModel& model = context.ensureModel();
    auto start = std::chrono::steady_clock::now();
    const SurfaceSample surface({&context.a, &context.b});
    const std::vector<Vec3> flats = surface.flatNormals(0.02, 6);
    SphereSearchOptions search;
    search.even = context.options.measure == Measure::OwnPart;
    SphereSearchStats stats;
    const auto found = searchSphere([&](const Vec3& u) { return model.at(u); }, flats, search, stats);
    result.evaluations = stats.evaluations;
    for (const DirectionCandidate& c : found)
        result.candidates.push_back({c.u, latLonOf(c.u, context.d_unit), c.source, c.v_estimate_mm3, {}});
    result.map = mapFromModel(model, context.d_unit, kMapStepDeg);
    result.time.search_s = secondsSince(start);
    start = std::chrono::steady_clock::now();
    verifyCandidates(context, result);
    result.time.exact_s += secondsSince(start);
    chooseSphereResult(context, result, surface, flats);
}

void checkSolids(OrientContext& context, OrientResult& result, Log& log) {
    const auto start = std::chrono::steady_clock::now();
    parallelFor(2, context.threads, [&](std::size_t k) {
        (k == 0 ? context.solid_a : context.solid_b) =
            std::make_unique<ExactSolid>(k == 0 ? context.a : context.b);
    });
    context.exact = context.solid_a->exact() && context.solid_b->exact();
    result.solid_a = describe(context.solid_a->status());
    result.solid_b = describe(context.solid_b->status());
    for (int k = 0; k < 2; ++k) {
        const ExactSolid& solid = k == 0 ? *context.solid_a : *context.solid_b;
        if (solid.exact())
            continue;
        const std::string name = k == 0 ? context.a.name : context.b.name;
        const std::string warning = "orient: part " + std::string(k == 0 ? "A" : "B") + " (" + name +
                                    ") is " + describe(solid.status()) +
                                    ": exact volumes are impossible, using the voxel measure instead";
        result.warnings.push_back(warning);
        log.warning(warning);
    }
    result.time.check_s = secondsSince(start);
}

}  // namespace

double OrientContext::exactOrEstimate(const Vec3& u) const {
    if (exact) {
        if (const auto v = exactInterference(*solid_a, *solid_b, u * offset_mm, options.measure))
            return *v;
    }
    return model->at(u);
}

const InterferenceModel& OrientContext::ensureModel() {
    if (!model)
        model.emplace(a, b, offset_mm, options.measure, options.resolution, threads);
    return *model;
}

VMap mapFromModel(const InterferenceModel& model, const Vec3& d_unit, double step_deg) {
    VMap map;
    map.step_deg = step_deg;
    map.rows = map.columns = static_cast<int>(std::lround(360.0 / step_deg));
    map.values.resize(static_cast<std::size_t>(map.rows) * map.columns);
    for (int r = 0; r < map.rows; ++r) {
        for (int c = 0; c < map.columns; ++c)
            map.values[r * map.columns + c] = model.at(offsetDirection(r * step_deg, c * step_deg, d_unit));
    }
    return map;
}

std::string methodName(Method method) {
    return method == Method::Sphere ? "sphere" : "grid";
}

std::string measureName(Measure measure) {
    return measure == Measure::OwnPart ? "own" : "all";
}

OrientResult optimiseOrientation(const Mesh& a, const Mesh& b, const Vec3& offset_mm,
                                 const OrientOptions& options, Log& log) {
    const auto start = std::chrono::steady_clock::now();
    if (std::abs(offset_mm.z) > 1e-9)
        throw InputError("orient: the nozzle offset must be horizontal (z = 0)");
    const double offset = length(offset_mm);
    if (offset <= 0)
        throw InputError("orient: the nozzle offset is zero: there is no interference to optimise");
    OrientContext context{
        a, b, options, effectiveThreads(options.threads), normalised(offset_mm), offset, {}, {}, false, {}};
    OrientResult result;
    result.method = options.method;
    result.measure = options.measure;
    result.offset_mm = offset_mm;
    const auto [a_min, a_max] = boundsMm(a);
    const auto [b_min, b_max] = boundsMm(b);
    result.centre_mm = {(std::min(a_min.x, b_min.x) + std::max(a_max.x, b_max.x)) / 2,
                        (std::min(a_min.y, b_min.y) + std::max(a_max.y, b_max.y)) / 2,
                        (std::min(a_min.z, b_min.z) + std::max(a_max.z, b_max.z)) / 2};
    checkSolids(context, result, log);
    auto voxel_start = std::chrono::steady_clock::now();
    context.ensureModel();
    result.time.voxel_s = secondsSince(voxel_start);
    result.exact = context.exact;
    result.volume_a_mm3 = context.exact ? context.solid_a->volumeMm3() : context.model->voxelVolumeMm3(0);
    result.volume_b_mm3 = context.exact ? context.solid_b->volumeMm3() : context.model->voxelVolumeMm3(1);
    result.v_before_estimate_mm3 = context.model->at(context.d_unit);
    result.v_before_mm3 = result.v_before_estimate_mm3;
    if (options.method == Method::Grid) {
        runGridMethod(context, result);
        const auto exact_start = std::chrono::steady_clock::now();
        result.v_before_mm3 = context.exactOrEstimate(context.d_unit);
        result.time.exact_s = secondsSince(exact_start);
    } else {
        runSphereMethod(context, result);
    }
    result.time.total_s = secondsSince(start);
    return result;
}

}  // namespace mixengine::orient
