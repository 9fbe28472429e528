#pragma once
// Cura's Slice message → the SliceRequest every slice starts from (pipeline/SliceRequest.h).
//
// What Cura sends (shared/reference/cura-integration.md §4) and where it goes:
//   global_settings      → request.user.global (every key, already evaluated by Cura)
//   extruders[i]         → request.user.extruders[id] (disabled trains included)
//   limit_to_extruder    → a global lookup of such a key reads the named extruder's value
//   object_lists[g]      → request.groups[g]; its settings are the mesh-group values
//   objects              → MeshInput: name, triangle soup (float32 x y z per corner, mm, Z up,
//                          origin at the plate centre), per-object settings (always extruder_nr)
// Settings arrive token-expanded and with the frontend's own keys, so the request is marked
// settings_from_frontend. Throws InputError naming the object or setting that is malformed.
#include "pipeline/SliceRequest.h"

namespace cura::proto {
class Slice;
}

namespace mixengine {

SliceRequest requestFromSlice(const cura::proto::Slice& slice);

/// Decodes an Object's vertex bytes (9 little-endian float32 per triangle). Throws InputError
/// naming `object_name` when the byte count is not a whole number of triangles or a value is
/// not finite.
TriangleSoup soupFromVertexBytes(const std::string& bytes, const std::string& object_name);

}  // namespace mixengine
