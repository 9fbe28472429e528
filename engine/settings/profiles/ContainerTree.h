#pragma once
// Which variants, materials, qualities and intents Cura 4.13 offers for one machine: its container
// tree (cura/Machines/MachineNode.py, VariantNode.py, MaterialNode.py, QualityNode.py), as queries.
//
// Machine metadata (inherited along the definition chain, MachineNode.__init__): has_materials
// (default true), has_variants (false), has_machine_quality (false), quality_definition (the
// machine's id; "fdmprinter" unless has_machine_quality), exclude_materials, preferred_variant_name,
// preferred_material, preferred_quality_type. (has_machine_materials and variants_name are not used
// by Cura 4.13's tree.)
//
// Variants: with has_variants, the variant files with definition = the machine and
//   hardware_type = nozzle, by name (the first of a name wins); otherwise, or when there are none,
//   the single "empty" variant.
// Materials of a variant (VariantNode._loadAll): without has_materials, only the empty material.
//   Otherwise one container per material file (base_file): its base container (definition
//   fdmprinter), replaced by the last container with definition = the machine (machine- or
//   hotend-specific, in registration order), replaced by the one for this variant's hotend name;
//   then containers whose *id* is in exclude_materials are dropped.
// Qualities of a material (MaterialNode._loadAll): without has_machine_quality, every quality with
//   definition fdmprinter; without has_materials, those of the quality_definition; otherwise those of
//   the quality_definition with material = the base_file (and variant = the variant's name when
//   has_variants), else those (same definition and variant) whose material is the base_file of any
//   material of the same material type, else those with a global_quality other than "False".
//   (Cura's third fallback, by GUID, queries a metadata key "guid" that no material has: never
//   matches.) No quality at all means the empty quality (quality_type "not_supported").
// Global qualities (MachineNode._loadAll): global_quality = True and definition = the
//   quality_definition, else definition fdmprinter.
// Intents of a quality (QualityNode._loadAll): definition = quality_definition, variant = the
//   variant's name, material = the quality's `material`, quality_type = the quality's; the empty
//   intent ("default") always exists. Global qualities have none.
// Where Cura's answer depends on its registry order (built from a Python set, so it can vary between
// runs), containers are taken in id order and Cura's own rule is applied to that order: a later
// container replaces an earlier one of the same quality type in Cura's dictionaries, and "the first"
// fallbacks take the first.
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "settings/DefinitionSet.h"
#include "settings/profiles/ProfileResources.h"

namespace mixengine {

struct MachineProfileInfo {
    std::string id;
    bool has_materials = true;
    bool has_variants = false;
    bool has_machine_quality = false;
    std::string quality_definition;
    std::vector<std::string> exclude_materials;
    std::string preferred_variant_name, preferred_material, preferred_quality_type;
};

/// Reads the metadata above from a loaded definition (metadata is inherited, as in Uranium).
MachineProfileInfo machineProfileInfo(const DefinitionSet& definitions);

struct VariantEntry {
    std::string name;                   ///< "empty" for the empty variant
    const InstCfgFile* file = nullptr;  ///< nullptr for the empty variant
};

class ContainerTree {
  public:
    /// `resources` must outlive the tree.
    ContainerTree(MachineProfileInfo machine, const ProfileResources& resources);

    const MachineProfileInfo& machine() const { return machine_; }
    const std::vector<VariantEntry>& variants() const { return variants_; }
    const VariantEntry* variant(std::string_view name) const;

    /// The materials of variant `variant_name`, in base_file order; an empty list means the empty
    /// material (no has_materials, or nothing left).
    std::vector<const MaterialContainer*> materials(const std::string& variant_name) const;

    /// The qualities of `material` (nullptr = the empty material) under variant `variant_name`; an
    /// empty list means the empty quality.
    std::vector<const InstCfgFile*> qualities(const std::string& variant_name,
                                              const MaterialContainer* material) const;

    /// Global qualities by quality_type, types in order of first appearance; for a type with
    /// several, the last (as MachineNode's dictionary keeps it).
    std::vector<std::pair<std::string, const InstCfgFile*>> globalQualities() const;

    /// The intents of extruder quality `quality` under variant `variant_name`.
    std::vector<const InstCfgFile*> intents(const std::string& variant_name,
                                            const InstCfgFile& quality) const;

  private:
    std::vector<const InstCfgFile*> qualitiesWhere(const std::string& definition, const std::string* variant,
                                                   const std::string* material) const;

    MachineProfileInfo machine_;
    const ProfileResources& resources_;
    std::vector<VariantEntry> variants_;
    std::vector<MaterialContainer> material_containers_;  ///< every material container for this machine
};

/// A metadata value: `file.meta(key)` or "" when absent.
std::string metaOr(const InstCfgFile& file, std::string_view key, const std::string& fallback = "");

}  // namespace mixengine
