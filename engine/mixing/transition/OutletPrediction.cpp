#include "mixing/transition/OutletPrediction.h"

#include <cmath>
#include <map>

#include "mixing/transition/StepContext.h"

namespace mixengine {
namespace {

using MixKey = std::array<long, kMaxMixChannels>;

/// Colours of mixes, looked up by the mix rounded to 1/1000 (colours closer than that are equal in 8 bits).
class ColorCache {
  public:
    ColorCache(const PigmentModel& model, PrintPlan& plan) : model_(model), plan_(plan) {}
    /// Index into plan.outlet_colors, and the colour's Lab.
    std::pair<int, Lab> of(const MixVector& mix) {
        MixKey key{};
        for (int c = 0; c < kMaxMixChannels; ++c)
            key[static_cast<std::size_t>(c)] = std::lround(mix[c] * 1000.0);
        auto it = index_.find(key);
        if (it == index_.end()) {
            MixVector rounded = mix;  // the colour of the key itself, whichever mix found it first
            for (int c = 0; c < kMaxMixChannels; ++c)
                rounded[c] = static_cast<double>(key[static_cast<std::size_t>(c)]) / 1000.0;
            const Lab lab = model_.predictLab(rounded);
            const Rgb rgb = model_.space().srgbOf(lab);
            const auto [known, added] = colors_.emplace(rgb, static_cast<int>(plan_.outlet_colors.size()));
            if (added)
                plan_.outlet_colors.push_back(rgb);
            it = index_.emplace(key, std::pair{known->second, lab}).first;
        }
        return it->second;
    }

  private:
    const PigmentModel& model_;
    PrintPlan& plan_;
    std::map<MixKey, std::pair<int, Lab>> index_;
    std::map<Rgb, int> colors_;  ///< index of each distinct colour in plan.outlet_colors
};

/// Where a visible extrusion is.
struct Where {
    int layer = 0;
    Point2 at{};
    Feature feature = Feature::Fill;
    int mesh = -1;
};

void measure(const Where& where, double length_mm, const Lab& asked, const Lab& out, double share_distance,
             double tolerance, VisibleReport& report) {
    const int mesh = where.mesh;
    const double de = deltaE00(asked, out);
    for (double* sum : {&report.visible_mm, &report.by_mesh[mesh].visible_mm})
        *sum += length_mm;
    for (double* sum : {&report.within_de_mm, &report.by_mesh[mesh].within_de_mm})
        *sum += de <= kVisibleDeltaE00 ? length_mm : 0.0;
    for (double* sum : {&report.within_share_mm, &report.by_mesh[mesh].within_share_mm})
        *sum += share_distance <= tolerance ? length_mm : 0.0;
    if (de > report.worst.delta_e00)
        report.worst = {de, share_distance, where.layer, where.at, where.feature};
}

}  // namespace

void VisibleReport::add(const VisibleReport& other) {
    visible_mm += other.visible_mm;
    within_de_mm += other.within_de_mm;
    within_share_mm += other.within_share_mm;
    if (other.worst.delta_e00 > worst.delta_e00)
        worst = other.worst;
}

VisibleReport predictOutlet(PrintPlan& plan, const std::vector<std::vector<StepTarget>>& targets,
                            std::optional<Chamber>& chamber, const ChamberSpec& spec, double tolerance,
                            const PigmentModel& model) {
    VisibleReport report;
    ColorCache colors(model, plan);
    std::map<int, Lab> asked;
    for (std::size_t l = 0; l < plan.layers.size(); ++l) {
        PlannedLayer& layer = plan.layers[l];
        std::optional<Point2> head;
        Feature feature = Feature::Fill;
        int mesh = -1;
        for (std::size_t k = 0; k < layer.steps.size(); ++k) {
            PlanStep& step = layer.steps[k];
            if (step.kind == PlanStep::Kind::SetFeature)
                feature = step.feature;
            if (step.kind == PlanStep::Kind::SetMesh)
                mesh = step.mesh_index;
            const std::optional<Point2> from = head;
            if (movesHead(step))
                head = step.to;
            if (step.kind != PlanStep::Kind::Extrude || step.mix < 0)
                continue;
            const MixVector& commanded = plan.mixes[static_cast<std::size_t>(step.mix)];
            if (!chamber)
                chamber.emplace(spec, commanded);
            const MixVector out = chamber->push(commanded, step.volume_mm3);
            const auto [color, out_lab] = colors.of(out);
            step.outlet_color = color;
            const StepTarget& t = targets[l][k];
            const int wanted = t.exact >= 0 ? t.exact : t.mix;  // a continuous field: its own value
            if (!t.visible || wanted < 0 || !from)
                continue;
            auto it = asked.find(wanted);
            if (it == asked.end())
                it = asked.emplace(wanted, model.predictLab(plan.mixes[static_cast<std::size_t>(wanted)]))
                         .first;
            measure({layer.index, step.to, feature, mesh}, distanceMm(*from, step.to), it->second, out_lab,
                    shareDistance(out, plan.mixes[static_cast<std::size_t>(wanted)]), tolerance, report);
        }
    }
    return report;
}

}  // namespace mixengine
