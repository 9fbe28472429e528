#pragma once
// The mixing stage: after planning, every extrusion step of a mesh group's plan gets a mix
// (PlanStep::mix, an index into PrintPlan::mixes). A mesh's extrusions follow that mesh's
// schedule (mixing/fields/MixSchedule.h) at the layer's height above the mesh's bottom (a spiral's moves,
// PlanStep::rise_um, at the height each ends at), in percent of the mesh's own height or in mm; non-mesh
// extrusions follow the group's settings over the height of all meshes together; the raft (its
// RaftBase/RaftInterface/RaftSurface extrusions) is printed with the group's mixing_raft_ratio (filament A by
// default), the support (normal and tree, body and interface, Support/SupportInterface) and the draft shield
// (DraftShield) with its mixing_support_ratio (filament A by default). The chamber-delay shift
// (mixing/chamber/ChamberDelay.h) is applied last, so the model's first colour is primed through the raft.
// In color mode every mesh prints the mix solved for its mixing_target_color (and gradient mode
// solves mixing_gradient_colors); each solved colour is reported (info: target, mix, predicted
// colour, ΔE00), and one warning line names a mesh whose target is outside the mixable gamut
// (ΔE00 above kGamutWarningDeltaE00), which is printed in the nearest mixable colour. A mesh
// with painted faces (3MF) gets painted regions (mixing/fields/PaintSchedule.h): its extrusions are cut
// where the region changes (mixing/fields/RegionSplit.h) and each piece takes its region's mix; the
// chamber delay then shifts all of them alike.
// In single mode (the default) the plan is left untouched: no mixes, every step's mix stays -1.
// Bad mixing settings throw InputError (mixing/setup/MixingSettings.h) before anything is written.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "common/Log.h"
#include "geometry/Point.h"
#include "mesh/Mesh.h"
#include "mixing/MixingReport.h"
#include "mixing/chamber/ChamberModel.h"
#include "planning/LayerPlan.h"
#include "settings/Settings.h"

namespace mixengine {

/// A mesh as the mixing stage sees it: its resolved settings and the heights it spans as placed on
/// the plate (microns, the same frame as PlannedLayer::z).
struct MixingMesh {
    const Settings* settings = nullptr;
    std::string name;  ///< named in colour reports and warnings
    coord_um bottom_um = 0;
    coord_um top_um = 0;
    const Mesh* mesh = nullptr;  ///< as placed (without the raft's lift); its painted faces make regions
    coord_um lift_um = 0;        ///< how far the printed layers are lifted above the mesh's frame (raft)
};

/// What the mixing stage needs of a mesh group. The pointed-to settings outlive the call.
struct MixingGroup {
    const Settings* settings = nullptr;  ///< the group's: non-mesh extrusions, dialect, chamber volume
    std::vector<MixingMesh> meshes;      ///< index = PlanStep::mesh_index of the plan's SetMesh steps
    /// What the chamber holds from the groups printed before (print_sequence one_at_a_time), updated by
    /// assignMixes; null or empty: a chamber full of this group's first mix.
    std::optional<Chamber>* chamber = nullptr;
    /// The XY rectangle of everything printed before this group, kept clear by the purge tower (empty: none).
    std::optional<std::pair<Point2, Point2>> printed_before;
    int threads = 1;  ///< threads the transition planner may use
};

/// Returns what a user needs to trust the print (mixing/MixingReport.h; `mixing` false in single mode).
MixingReport assignMixes(PrintPlan& plan, const MixingGroup& group, Log& log);

}  // namespace mixengine
