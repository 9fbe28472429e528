#include "mixing/transition/LayerOrder.h"

#include <algorithm>
#include <optional>

#include "mixing/chamber/ChamberModel.h"
#include "mixing/transition/StepContext.h"

namespace mixengine {
namespace {

struct Segment {
    std::size_t begin = 0, end = 0;  ///< steps [begin, end)
    int mix = -1;
    bool visible = false;
    StepContext before;  ///< the markers in force and the head's place at `begin`
};

bool reorderable(const PlannedLayer& layer) {
    for (const PlanStep& step : layer.steps) {
        const bool special = step.kind == PlanStep::Kind::SetExtruder || step.kind == PlanStep::Kind::Prime ||
                             step.kind == PlanStep::Kind::WipeScript;
        if (special || step.rise_um > 0)
            return false;
    }
    return true;
}

/// The segments of the steps before `tail` (the first step after the last extrusion). A segment
/// ends at its last extrusion; the steps after it lead into the next one.
std::vector<Segment> segmentsOf(const PlannedLayer& layer, const std::vector<StepTarget>& targets,
                                std::size_t tail) {
    std::vector<Segment> segments;
    std::size_t begin = 0;
    for (std::size_t i = 0; i < tail; ++i) {
        if (layer.steps[i].kind != PlanStep::Kind::Extrude)
            continue;
        const StepTarget& t = targets[i];
        if (!segments.empty() && segments.back().mix == t.mix && segments.back().visible == t.visible)
            segments.back().end = i + 1;
        else
            segments.push_back({begin, i + 1, t.mix, t.visible, {}});
        begin = i + 1;
    }
    return segments;
}

/// The markers and start of a segment, recorded where its lead-in begins.
void fixLeadIns(const PlannedLayer& layer, std::vector<Segment>& segments) {
    StepContext context;
    std::size_t next = 0;
    for (std::size_t i = 0; i < layer.steps.size() && next < segments.size(); ++i) {
        for (; next < segments.size() && segments[next].begin == i; ++next)
            segments[next].before = context;
        context.advance(layer.steps[i]);
    }
}

/// The visible mixes in print order: `last_mix` (or the nearest to it) first, then nearest-next.
std::vector<int> groupOrder(const std::vector<Segment>& segments, int last_mix,
                            const std::vector<MixVector>& mixes) {
    std::vector<int> left;
    for (const Segment& s : segments)
        if (s.visible && std::find(left.begin(), left.end(), s.mix) == left.end())
            left.push_back(s.mix);
    std::vector<int> order;
    int current = last_mix;
    while (!left.empty()) {
        auto best = left.begin();
        if (current >= 0) {
            const MixVector& from = mixes[static_cast<std::size_t>(current)];
            best = std::min_element(left.begin(), left.end(), [&](int a, int b) {
                return shareDistance(from, mixes[static_cast<std::size_t>(a)]) <
                       shareDistance(from, mixes[static_cast<std::size_t>(b)]);
            });
        }
        current = *best;
        order.push_back(current);
        left.erase(best);
    }
    return order;
}

void append(std::vector<std::size_t>& order, const std::vector<Segment>& segments, int mix, bool visible) {
    for (std::size_t s = 0; s < segments.size(); ++s)
        if (segments[s].mix == mix && segments[s].visible == visible)
            order.push_back(s);
}

/// Segment indices in their new order.
std::vector<std::size_t> segmentOrder(const std::vector<Segment>& segments, const std::vector<int>& groups,
                                      int last_mix) {
    std::vector<std::size_t> orphans;
    for (std::size_t s = 0; s < segments.size(); ++s)
        if (std::find(groups.begin(), groups.end(), segments[s].mix) == groups.end())
            orphans.push_back(s);
    std::vector<std::size_t> order;
    const bool holds_first = groups.front() == last_mix;
    if (!holds_first)
        order.insert(order.end(), orphans.begin(), orphans.end());
    for (std::size_t g = 0; g < groups.size(); ++g) {
        const bool visible_first = g == 0 && holds_first;
        append(order, segments, groups[g], visible_first);
        append(order, segments, groups[g], !visible_first);
        if (g == 0 && holds_first)
            order.insert(order.end(), orphans.begin(), orphans.end());
    }
    return order;
}

const PlanStep* travelTemplate(const PlannedLayer& layer) {
    for (const PlanStep& step : layer.steps)
        if (step.kind == PlanStep::Kind::Travel)
            return &step;
    return nullptr;
}

/// Whether the segment's first move is a travel (it then needs no travel to its start).
bool startsWithTravel(const PlannedLayer& layer, const Segment& segment) {
    for (std::size_t i = segment.begin; i < segment.end; ++i)
        if (movesHead(layer.steps[i]))
            return layer.steps[i].kind == PlanStep::Kind::Travel;
    return false;
}

/// The steps that let a segment print out of its original order: the markers in force where it began and
/// a retracting travel there (none when the segment starts with a travel of its own; orderByMix checks).
void leadIn(const Segment& segment, const PlanStep& travel, OrderedLayer& out) {
    out.targets.resize(out.targets.size() + segment.before.resumeInto(travel, out.steps));
}

}  // namespace

bool visibleFeature(Feature feature) {
    return feature == Feature::WallOuter || feature == Feature::Skin || feature == Feature::Ironing ||
           feature == Feature::Roofing;
}

OrderedLayer orderByMix(const PlannedLayer& layer, const std::vector<StepTarget>& targets, int last_mix,
                        const std::vector<MixVector>& mixes) {
    OrderedLayer out{layer.steps, targets, false};
    std::size_t tail = 0;
    for (std::size_t i = 0; i < layer.steps.size(); ++i)
        if (layer.steps[i].kind == PlanStep::Kind::Extrude)
            tail = i + 1;
    const PlanStep* travel = travelTemplate(layer);
    if (tail == 0 || !travel || !reorderable(layer))
        return out;
    std::vector<Segment> segments = segmentsOf(layer, targets, tail);
    fixLeadIns(layer, segments);
    const std::vector<int> groups = groupOrder(segments, last_mix, mixes);
    if (groups.empty())
        return out;
    const std::vector<std::size_t> order = segmentOrder(segments, groups, last_mix);
    out.steps.clear();
    out.targets.clear();
    for (std::size_t k = 0; k < order.size(); ++k) {
        const Segment& s = segments[order[k]];
        const bool in_place = k == 0 ? order[k] == 0 : order[k] == order[k - 1] + 1;
        if (!in_place) {
            if (!s.before.head() && !startsWithTravel(layer, s))
                return {layer.steps, targets, false};
            leadIn(s, *travel, out);
            out.reordered = true;
        }
        out.steps.insert(out.steps.end(), layer.steps.begin() + static_cast<std::ptrdiff_t>(s.begin),
                         layer.steps.begin() + static_cast<std::ptrdiff_t>(s.end));
        out.targets.insert(out.targets.end(), targets.begin() + static_cast<std::ptrdiff_t>(s.begin),
                           targets.begin() + static_cast<std::ptrdiff_t>(s.end));
    }
    out.steps.insert(out.steps.end(), layer.steps.begin() + static_cast<std::ptrdiff_t>(tail),
                     layer.steps.end());
    out.targets.insert(out.targets.end(), targets.begin() + static_cast<std::ptrdiff_t>(tail), targets.end());
    return out;
}

}  // namespace mixengine
