#pragma once
// Replays what Cura 4.13's CuraStackBuilder and MachineManager do to one printer's stacks when it is
// added and when its variant, material, quality or intent is changed (the steps are described in
// settings/profiles/ProfileSelector.h). Holds the current choice per stack; the containers belong to
// the ContainerTree / ProfileResources it was built from.
#include <map>
#include <string>
#include <vector>

#include "settings/DefinitionSet.h"
#include "settings/profiles/ContainerTree.h"

namespace mixengine {

struct ExtruderChoice {
    const VariantEntry* variant = nullptr;
    const MaterialContainer* material = nullptr;  ///< nullptr: empty_material
    const InstCfgFile* quality = nullptr;         ///< nullptr: empty_quality
    const InstCfgFile* intent = nullptr;          ///< nullptr: empty_intent
};

class CuraSession {
  public:
    /// Adds the printer (CuraStackBuilder.createMachine): every stack gets Cura's defaults.
    CuraSession(const DefinitionSet& definitions, const ContainerTree& tree);

    /// round(material_diameter) for extruder `position` seen from `variant` downwards.
    int approximateDiameter(int position, const VariantEntry* variant) const;

    void setVariant(int position, const VariantEntry& variant);         ///< MachineManager.setVariant
    void setMaterial(int position, const MaterialContainer& material);  ///< MachineManager.setMaterial
    /// setQualityGroupByQualityType; throws InputError when the type is not available.
    void setQualityType(const std::string& quality_type);
    /// setIntentByCategory; throws InputError when no extruder has an intent of that category.
    void setIntentCategory(const std::string& category);

    /// The quality type of a quality container id offered for this set-up, or "".
    std::string qualityTypeOfId(const std::string& id) const;

    const InstCfgFile* globalQuality() const { return global_quality_; }
    const std::vector<ExtruderChoice>& extruders() const { return extruders_; }

  private:
    struct QualityGroup {
        const InstCfgFile* global = nullptr;
        std::map<int, const InstCfgFile*> extruders;
        bool available = false;
    };
    std::map<std::string, QualityGroup> qualityGroups() const;
    std::vector<std::string> availableTypes() const;
    const MaterialContainer* preferredMaterial(const std::string& variant_name,
                                               int approximate_diameter) const;
    const InstCfgFile* preferredQuality(const ExtruderChoice& extruder) const;
    void updateMaterialWithVariant(int position);
    void updateQualityWithMaterial();
    void applyQualityGroup(const QualityGroup& group);
    void updateIntentWithQuality();
    void applyIntentCategory(const std::string& category);

    const DefinitionSet& definitions_;
    const ContainerTree& tree_;
    const InstCfgFile* global_quality_ = nullptr;
    std::vector<ExtruderChoice> extruders_;
};

/// An intent's category (Cura's default for a missing entry is "default").
std::string intentCategory(const InstCfgFile* intent);

}  // namespace mixengine
