#include "settings/profiles/CuraSession.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <set>

#include "common/Error.h"
#include "settings/profiles/ProfileNames.h"

namespace mixengine {
namespace {

std::optional<double> number(const std::string& text) {
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size())
        return std::nullopt;
    return v;
}

/// A definition's material_diameter: its `value` when that is a plain number, else default_value.
std::optional<double> definitionDiameter(const SettingDefinition* def) {
    if (!def)
        return std::nullopt;
    if (def->value_formula) {
        if (auto v = number(*def->value_formula))
            return v;
    }
    return number(def->default_value);
}

std::string qualityType(const InstCfgFile* quality) {
    return quality ? metaOr(*quality, "quality_type") : "not_supported";
}

}  // namespace

std::string intentCategory(const InstCfgFile* intent) {
    return intent ? metaOr(*intent, "intent_category", "default") : "default";
}

CuraSession::CuraSession(const DefinitionSet& definitions, const ContainerTree& tree)
    : definitions_(definitions), tree_(tree) {
    const MachineProfileInfo& machine = tree_.machine();
    const auto global = tree_.globalQualities();  // preferredGlobalQuality
    auto preferred = std::find_if(global.begin(), global.end(),
                                  [&](const auto& e) { return e.first == machine.preferred_quality_type; });
    if (preferred != global.end())
        global_quality_ = preferred->second;
    else if (!global.empty())
        global_quality_ = global.front().second;
    const VariantEntry* variant = tree_.variant(machine.preferred_variant_name);
    if (!variant)
        variant = &tree_.variants().front();
    for (const ExtruderDefinition& extruder : definitions_.extruders) {
        ExtruderChoice choice;
        choice.variant = variant;
        choice.material = preferredMaterial(variant->name, approximateDiameter(extruder.position, nullptr));
        choice.quality = preferredQuality(choice);
        extruders_.resize(
            std::max<std::size_t>(extruders_.size(), static_cast<std::size_t>(extruder.position) + 1));
        extruders_[static_cast<std::size_t>(extruder.position)] = choice;
    }
    for (std::size_t position = 0; position < extruders_.size(); ++position) {
        ExtruderChoice& choice = extruders_[position];
        if (choice.variant)
            continue;  // a gap in the extruder positions gets the defaults too
        choice.variant = variant;
        choice.material =
            preferredMaterial(variant->name, approximateDiameter(static_cast<int>(position), nullptr));
        choice.quality = preferredQuality(choice);
    }
}

int CuraSession::approximateDiameter(int position, const VariantEntry* variant) const {
    std::optional<double> diameter;
    if (variant && variant->file) {
        for (const auto& [key, text] : variant->file->values) {
            if (key == "material_diameter" && !containerValueFromText(text).is_formula)
                diameter = number(text);
        }
    }
    for (const ExtruderDefinition& extruder : definitions_.extruders) {
        if (!diameter && extruder.position == position) {
            auto it = extruder.overrides.find("material_diameter");
            diameter = definitionDiameter(it == extruder.overrides.end() ? nullptr : &it->second);
        }
    }
    if (!diameter)
        diameter = definitionDiameter(definitions_.find("material_diameter"));
    return static_cast<int>(std::nearbyint(diameter.value_or(2.85)));
}

const MaterialContainer* CuraSession::preferredMaterial(const std::string& variant_name, int diameter) const {
    const std::vector<const MaterialContainer*> materials = tree_.materials(variant_name);
    const std::string& preferred = tree_.machine().preferred_material;
    for (const std::string& base : {preferred, diameter == 2 ? preferred + "_175" : std::string()}) {
        for (const MaterialContainer* m : materials) {
            if (!base.empty() && m->profile->base_file == base &&
                m->profile->approximate_diameter == diameter)
                return m;
        }
    }
    for (const MaterialContainer* m : materials) {
        if (m->profile->approximate_diameter == diameter)
            return m;
    }
    return materials.empty() ? nullptr : materials.front();
}

const InstCfgFile* CuraSession::preferredQuality(const ExtruderChoice& extruder) const {
    const auto qualities = tree_.qualities(extruder.variant->name, extruder.material);
    for (const InstCfgFile* q : qualities) {
        if (metaOr(*q, "quality_type") == tree_.machine().preferred_quality_type)
            return q;
    }
    return qualities.empty() ? nullptr : qualities.front();
}

void CuraSession::setVariant(int position, const VariantEntry& variant) {
    extruders_.at(static_cast<std::size_t>(position)).variant = &variant;
    updateMaterialWithVariant(position);
    updateQualityWithMaterial();
}

void CuraSession::updateMaterialWithVariant(int position) {
    ExtruderChoice& e = extruders_.at(static_cast<std::size_t>(position));
    const int old_diameter = e.material ? e.material->profile->approximate_diameter : 3;
    const int new_diameter = approximateDiameter(position, e.variant);
    const std::string base = e.material ? e.material->profile->base_file : "empty_material";
    for (const MaterialContainer* m : tree_.materials(e.variant->name)) {
        if (new_diameter == old_diameter && m->profile->base_file == base) {
            e.material = m;
            return;
        }
    }
    e.material = preferredMaterial(e.variant->name, new_diameter);
}

void CuraSession::setMaterial(int position, const MaterialContainer& material) {
    extruders_.at(static_cast<std::size_t>(position)).material = &material;
    updateQualityWithMaterial();
}

std::map<std::string, CuraSession::QualityGroup> CuraSession::qualityGroups() const {
    std::vector<std::map<std::string, const InstCfgFile*>> per_extruder;
    for (const ExtruderChoice& e : extruders_) {
        std::map<std::string, const InstCfgFile*> by_type;
        for (const InstCfgFile* q : tree_.qualities(e.variant->name, e.material))
            by_type[metaOr(*q, "quality_type")] = q;  // getQualityGroups: the last of a type wins
        if (by_type.empty())
            by_type.emplace("not_supported", nullptr);
        per_extruder.push_back(std::move(by_type));
    }
    auto global = tree_.globalQualities();
    if (global.empty())
        global.emplace_back("not_supported", nullptr);
    std::map<std::string, QualityGroup> groups;
    for (const auto& [type, quality] : global) {
        QualityGroup& group = groups[type];
        group.global = quality;
        group.available = true;
        for (std::size_t i = 0; i < per_extruder.size(); ++i) {
            auto it = per_extruder[i].find(type);
            if (it != per_extruder[i].end())
                group.extruders[static_cast<int>(i)] = it->second;
            else
                group.available = false;
        }
    }
    return groups;
}

std::vector<std::string> CuraSession::availableTypes() const {
    std::vector<std::string> types;
    for (const auto& [type, group] : qualityGroups()) {
        if (group.available)
            types.push_back(type);
    }
    return types;
}

void CuraSession::updateQualityWithMaterial() {
    const std::string current = qualityType(global_quality_);
    bool compatible = true;
    for (const ExtruderChoice& e : extruders_)
        compatible = compatible && e.material && e.material->compatible;
    const std::vector<std::string> available = availableTypes();  // sorted
    if ((tree_.machine().has_materials && !compatible) || available.empty()) {
        applyQualityGroup(QualityGroup{});  // everything "Not supported"
        return;
    }
    std::string type = available.front();
    if (std::find(available.begin(), available.end(), current) != available.end())
        type = current;
    else if (std::find(available.begin(), available.end(), tree_.machine().preferred_quality_type) !=
             available.end())
        type = tree_.machine().preferred_quality_type;
    applyQualityGroup(qualityGroups().at(type));
}

void CuraSession::applyQualityGroup(const QualityGroup& group) {
    global_quality_ = group.global;
    if (!group.global && group.extruders.empty()) {  // _setEmptyQuality
        for (ExtruderChoice& e : extruders_)
            e.quality = nullptr;
    }
    for (const auto& [position, quality] : group.extruders)
        extruders_.at(static_cast<std::size_t>(position)).quality = quality;
    updateIntentWithQuality();
}

void CuraSession::setQualityType(const std::string& quality_type) {
    const auto groups = qualityGroups();
    auto it = groups.find(quality_type);
    if (it == groups.end() || !it->second.available)
        throw InputError(
            "--quality '" + quality_type + "': not available for " + tree_.machine().id +
            " with the chosen variant(s) and material(s); available: " + shortList(availableTypes()));
    applyQualityGroup(it->second);
}

void CuraSession::updateIntentWithQuality() {
    std::string category = "default";
    for (const ExtruderChoice& e : extruders_) {
        const std::string current = intentCategory(e.intent);
        if (current != "default" && current != category)
            category = current;
    }
    applyIntentCategory(category);
}

void CuraSession::applyIntentCategory(const std::string& category) {
    for (ExtruderChoice& e : extruders_) {
        if (!e.quality) {
            e.intent = nullptr;
            continue;
        }
        const auto offered = tree_.qualities(e.variant->name, e.material);
        if (std::find(offered.begin(), offered.end(), e.quality) == offered.end())
            continue;  // Cura: "not supported according to the container tree"; the intent stays
        e.intent = nullptr;
        for (const InstCfgFile* intent : tree_.intents(e.variant->name, *e.quality)) {
            if (intentCategory(intent) == category) {
                e.intent = intent;
                break;
            }
        }
    }
}

void CuraSession::setIntentCategory(const std::string& category) {
    applyIntentCategory(category);
    if (category == "default")
        return;
    std::set<std::string> offered;
    bool any = false;
    for (const ExtruderChoice& e : extruders_) {
        any = any || intentCategory(e.intent) == category;
        for (const InstCfgFile* intent :
             e.quality ? tree_.intents(e.variant->name, *e.quality) : std::vector<const InstCfgFile*>{})
            offered.insert(intentCategory(intent));
    }
    if (!any)
        throw InputError("--intent '" + category + "': not available for " + tree_.machine().id +
                         " with quality '" + qualityType(global_quality_) +
                         "' and the chosen material(s); available: default" +
                         (offered.empty() ? "" : ", " + shortList({offered.begin(), offered.end()})));
}

std::string CuraSession::qualityTypeOfId(const std::string& id) const {
    for (const auto& [type, group] : qualityGroups()) {
        if (group.global && group.global->id == id)
            return type;
        for (const auto& [position, quality] : group.extruders) {
            if (quality && quality->id == id)
                return type;
        }
    }
    return {};
}

}  // namespace mixengine
