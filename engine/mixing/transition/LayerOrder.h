#pragma once
// Transition planning, the order inside a layer (issue 26). A mixing chamber smears every change of
// mix over tens of mm³, so a layer whose extrusions ask for several mixes is reordered so that the
// extrusions of one mix print together and the chamber changes as few times as possible:
//
//  - the layer's steps are cut into segments: runs of steps whose extrusions want one mix and are
//    all visible or all hidden (a step that does not extrude belongs to the extrusion after it; the
//    steps after the last extrusion stay at the layer's end);
//  - the visible mixes (groups) are ordered greedily: first the mix the chamber was last commanded
//    (or the nearest to it), then each time the nearest remaining one — so with two mixes the order
//    alternates layer by layer and each layer needs one change;
//  - a group prints its hidden segments (infill, inner walls, hidden skin) before its visible ones,
//    so that they absorb the change into it — except the first group when the chamber already holds
//    its mix: that one prints visible first and hidden last, absorbing the change to the next group;
//  - hidden segments of mixes no visible extrusion of the layer asks for (support, the raft, a model's
//    unpainted inside) go into the first change (or at the layer's end when there is none).
//
// A segment printed out of its original order is preceded by the ;MESH:, ;TYPE: and fan steps in
// force where it began and a retracting travel to where it began, so it prints as planned. Layers with
// tool changes, primes, wipe scripts or a spiral are left as they are.
#include <vector>

#include "planning/LayerPlan.h"

namespace mixengine {

/// What the mixing stage wants of one step: the mix its material should have when it leaves the
/// nozzle (index into PrintPlan::mixes; −1 for a step that does not extrude) and whether it is seen.
struct StepTarget {
    int mix = -1;
    bool visible = false;
    /// A continuous field's own mix here (index into PrintPlan::mixes; mixing/fields/RegionField.h
    /// exactMixAt), of which `mix` is the band's approximation; −1: `mix` is meant
    int exact = -1;
    /// A hidden extrusion asking for its model's core mix (mixing_core_ratio): wished for, never at the
    /// cost of the visible surface
    bool core = false;
};

struct OrderedLayer {
    std::vector<PlanStep> steps;
    std::vector<StepTarget> targets;  ///< index for index with `steps` (−1 for inserted steps)
    bool reordered = false;           ///< false: the layer's own steps, unchanged
};

/// `targets`: one per step of `layer`; `last_mix` the mix the chamber was last commanded (−1: none);
/// `mixes` the plan's mix table (their distances order the groups).
OrderedLayer orderByMix(const PlannedLayer& layer, const std::vector<StepTarget>& targets, int last_mix,
                        const std::vector<MixVector>& mixes);

/// Features a person sees on the finished part: the outer wall, skin, roofing and ironing.
bool visibleFeature(Feature feature);

}  // namespace mixengine
