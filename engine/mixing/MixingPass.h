#pragma once
// The mixing stage: after planning, every extrusion step of a mesh group's plan gets a mix
// (PlanStep::mix, an index into PrintPlan::mixes). A mesh's extrusions follow that mesh's
// schedule (mixing/MixSchedule.h) at the layer's height above the mesh's bottom (a spiral's moves,
// PlanStep::rise_um, at the height each ends at), in percent of the mesh's own height or in mm; non-mesh
// extrusions follow the group's settings over the height of all meshes together; the raft (its
// RaftBase/RaftInterface/RaftSurface extrusions) is printed with the group's mixing_raft_ratio (filament A by
// default), the support (normal and tree, body and interface, Support/SupportInterface) and the draft shield
// (DraftShield) with its mixing_support_ratio (filament A by default). The chamber-delay shift
// (mixing/ChamberDelay.h) is applied last, so the model's first colour is primed through the raft. In single
// mode (the default) the plan is left untouched: no mixes, every step's mix stays -1. Bad mixing settings
// throw InputError (mixing/MixingSettings.h) before anything is written.
#include <vector>

#include "common/Log.h"
#include "geometry/Point.h"
#include "planning/LayerPlan.h"
#include "settings/Settings.h"

namespace mixengine {

/// A mesh as the mixing stage sees it: its resolved settings and the heights it spans as placed on
/// the plate (microns, the same frame as PlannedLayer::z).
struct MixingMesh {
    const Settings* settings = nullptr;
    coord_um bottom_um = 0;
    coord_um top_um = 0;
};

/// What the mixing stage needs of a mesh group. The pointed-to settings outlive the call.
struct MixingGroup {
    const Settings* settings = nullptr;  ///< the group's: non-mesh extrusions, dialect, chamber volume
    std::vector<MixingMesh> meshes;      ///< index = PlanStep::mesh_index of the plan's SetMesh steps
};

void assignMixes(PrintPlan& plan, const MixingGroup& group, Log& log);

}  // namespace mixengine
