#pragma once
// Chooses Cura's variant, material, quality and intent containers for a machine the way Cura 4.13
// does when a printer is added and the user then picks profiles, and turns them into the
// ProfileStack the StackEvaluator reads (settings/ProfileStack.h).
//
// The steps replay Cura's own code paths, in the order a user (or tests/e2e) drives them:
//  1. Adding the printer (cura/Settings/CuraStackBuilder.py createMachine):
//     global quality = the global quality of preferred_quality_type, else the first one;
//     each extruder: variant = preferred_variant_name, else the first; material = the variant's
//     preferred material for the extruder's approximate filament diameter (VariantNode
//     preferredMaterial: preferred_material with that diameter, else preferred_material + "_175"
//     when the diameter is 2, else the first material of that diameter, else the first);
//     quality = the material's first quality of preferred_quality_type, else its first quality;
//     intent = empty. The diameter is round(material_diameter) of the extruder definition
//     (Python rounding, half to even).
//  2. Each named variant (MachineManager.setVariant): the extruder keeps its material when the new
//     variant has that base_file and the diameter is unchanged, else gets the preferred material;
//     then the quality is updated (below).
//  3. Each named material (MachineManager.setMaterial), then the quality is updated.
//     Quality update (MachineManager._updateQualityWithMaterial): with has_materials and an
//     incompatible material ("hardware compatible" = no) every quality becomes empty ("Not
//     supported"); otherwise the quality type in use is kept when available, else
//     preferred_quality_type when available, else the alphabetically first available type; none
//     available → empty. A type is available when the machine has a global quality of that type
//     and every extruder's material has a quality of that type.
//  4. A named quality (setQualityGroupByQualityType): global and extruder qualities of that type.
//  5. A named intent (setIntentByCategory): each extruder gets its quality's intent of that
//     category, or the empty intent. The global stack's intent is always empty in Cura.
//
// Names (ProfileSelection): "" = keep Cura's default. Variant and material may be a comma-separated
// list, one entry per extruder; a single entry applies to every extruder.
//   variant:  its name ("AA 0.4", "0.4mm Nozzle"), its container id ("ultimaker_s5_aa04"), or a
//             unique case- and space-insensitive prefix of a name ("aa0.4", "0.4mm").
//   material: a base_file ("generic_pla_175"), a container id ("generic_pla_175_creality_ender3"),
//             or a display name ("Generic PLA"); a base_file X also finds X_175 when X is not there
//             or is for other filament. The material must match the extruder's filament diameter.
//   quality:  a quality_type ("standard", "normal") or a quality container id.
//   intent:   an intent_category ("engineering") or an intent container id, which also selects
//             that intent's quality type; "default" = no intent.
// A name that matches nothing, or a quality / intent that is not available with the chosen
// materials, is an InputError listing what is available.
//
// Containers enter the stack top first: extruder N [intent, quality, material, variant], global
// [quality]; empty containers are left out. Values of keys the machine does not define are dropped
// (Uranium's InstanceContainer ignores them too).
#include <filesystem>
#include <vector>

#include "settings/DefinitionSet.h"
#include "settings/ProfileStack.h"
#include "settings/profiles/ProfileResources.h"
#include "settings/profiles/ProfileSelection.h"

namespace mixengine {

/// The selection for `definitions` from already loaded resources.
ProfileStack selectProfiles(const DefinitionSet& definitions, const ProfileSelection& selection,
                            const ProfileResources& resources);

/// Loads the resources found through `search_path` (profileRoots) and selects.
ProfileStack selectProfiles(const DefinitionSet& definitions, const ProfileSelection& selection,
                            const std::vector<std::filesystem::path>& search_path);

}  // namespace mixengine
