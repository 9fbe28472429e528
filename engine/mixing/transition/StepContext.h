#pragma once
// Where a layer's steps stand before a given step: the ;MESH:, ;TYPE: and fan steps in force and the
// head's position. The mixing stage prints runs of steps elsewhere than planned
// (mixing/transition/LayerOrder.h moves segments, mixing/transition/TransitionPlan.h visits the purge tower);
// to carry on as planned it repeats those markers and travels, retracting, back to where the run began.
#include <optional>
#include <vector>

#include "planning/LayerPlan.h"

namespace mixengine {

/// Travel, extrusion and the lift of cool_lift_head end with the head at PlanStep::to.
inline bool movesHead(const PlanStep& step) {
    return step.kind == PlanStep::Kind::Travel || step.kind == PlanStep::Kind::Extrude ||
           step.kind == PlanStep::Kind::LiftHead;
}

class StepContext {
  public:
    /// Takes in the next step of the layer.
    void advance(const PlanStep& step) {
        if (step.kind == PlanStep::Kind::SetMesh)
            mesh_ = step;
        if (step.kind == PlanStep::Kind::SetFeature)
            feature_ = step;
        if (step.kind == PlanStep::Kind::SetFan)
            fan_ = step;
        if (movesHead(step))
            head_ = step.to;
    }
    const std::optional<Point2>& head() const { return head_; }
    /// Appends the markers in force (mesh, feature, fan) and, when the head's place is known, a copy of
    /// `travel` that retracts and goes there. Returns how many steps it appended.
    std::size_t resumeInto(const PlanStep& travel, std::vector<PlanStep>& out) const {
        const std::size_t before = out.size();
        for (const std::optional<PlanStep>* marker : {&mesh_, &feature_, &fan_})
            if (*marker)
                out.push_back(**marker);
        if (head_) {
            PlanStep back = travel;
            back.to = *head_;
            back.retract = true;
            back.prime_first = false;
            out.push_back(back);
        }
        return out.size() - before;
    }

  private:
    std::optional<PlanStep> mesh_, feature_, fan_;
    std::optional<Point2> head_;
};

}  // namespace mixengine
