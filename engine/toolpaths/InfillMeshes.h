#pragma once
// Every mesh's toolpaths in a group, with Cura's per-model roles (slicing/MultiVolumes.h VolumeRole),
// as CuraEngine 4.13 processes them:
//   - meshes are taken in infill_mesh_order (equal orders: in the order given);
//   - an infill mesh (infill_mesh) prints only inside the infill of the meshes before it: its
//     outline on each layer becomes the union of its overlap with their own infill areas, and they
//     lose its whole outline from the infill they print themselves (their walls, skin, perimeter
//     gaps and combing stay as they were). Inside, the infill mesh prints walls, skin and infill
//     with its own settings (toolpaths/MeshToolpaths.h); alone it prints nothing;
//   - support meshes and support blockers print nothing here (toolpaths/support/Support.h uses them): they
//     get empty layers, so that every mesh keeps its index (;MESH: order, mixing);
//   - every other mesh (cutting meshes, already carved, included) prints as usual.
// MeshToolpaths::sliced points at the input's layers for meshes that print alone, and is null for
// modifiers (their outlines neither comb nor count as model elsewhere).
#include <vector>

#include "toolpaths/GroupToolpaths.h"

namespace mixengine {

std::vector<MeshToolpaths> generateModelToolpaths(const ToolpathInput& input, int threads);

}  // namespace mixengine
