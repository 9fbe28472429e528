#pragma once
// The mixing stage: after planning, every extrusion step of a mesh group's plan gets a mix
// (PlanStep::mix, an index into PrintPlan::mixes). A mesh's extrusions follow that mesh's
// schedule (mixing/MixSchedule.h) at the layer's height above the mesh's bottom, in percent of the
// mesh's own height or in mm; non-mesh extrusions follow the group's settings over the height of
// all meshes together. The chamber-delay shift (mixing/ChamberDelay.h) is applied last.
// In single mode (the default) the plan is left untouched: no mixes, every step's mix stays -1.
// Bad mixing settings throw InputError (mixing/MixingSettings.h) before anything is written.
#include "common/Log.h"
#include "planning/LayerPlan.h"

namespace mixengine {

struct SceneGroup;

void assignMixes(PrintPlan& plan, const SceneGroup& group, Log& log);

}  // namespace mixengine
