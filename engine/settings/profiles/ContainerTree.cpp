#include "settings/profiles/ContainerTree.h"

#include <algorithm>
#include <set>

namespace mixengine {
namespace {

/// Uranium's parseBool over the str() form of a metadata value.
bool parseBool(const std::string& text) {
    return text == "True" || text == "true" || text == "Yes" || text == "yes" || text == "1";
}

/// The quoted strings of a Python list's str(), e.g. "['a', \"b'c\"]" → {a, b'c}.
std::vector<std::string> pythonStringList(const std::string& text) {
    std::vector<std::string> items;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char quote = text[i];
        if (quote != '\'' && quote != '"')
            continue;
        std::string item;
        for (++i; i < text.size() && text[i] != quote; ++i) {
            if (text[i] == '\\' && i + 1 < text.size())
                ++i;
            item += text[i];
        }
        items.push_back(std::move(item));
    }
    return items;
}

const std::string* lookup(const std::map<std::string, std::string>& metadata, const char* key) {
    auto it = metadata.find(key);
    return it == metadata.end() ? nullptr : &it->second;
}

}  // namespace

std::string metaOr(const InstCfgFile& file, std::string_view key, const std::string& fallback) {
    const std::string* value = file.meta(key);
    return value ? *value : fallback;
}

MachineProfileInfo machineProfileInfo(const DefinitionSet& definitions) {
    const auto& meta = definitions.metadata;
    auto text = [&](const char* key, const char* fallback) {
        const std::string* v = lookup(meta, key);
        return v ? *v : std::string(fallback);
    };
    MachineProfileInfo info;
    info.id = definitions.machine_id;
    info.has_materials = parseBool(text("has_materials", "true"));
    info.has_variants = parseBool(text("has_variants", "false"));
    info.has_machine_quality = parseBool(text("has_machine_quality", "false"));
    info.quality_definition =
        info.has_machine_quality ? text("quality_definition", info.id.c_str()) : "fdmprinter";
    info.exclude_materials = pythonStringList(text("exclude_materials", "[]"));
    info.preferred_variant_name = text("preferred_variant_name", "");
    info.preferred_material = text("preferred_material", "");
    info.preferred_quality_type = text("preferred_quality_type", "");
    return info;
}

ContainerTree::ContainerTree(MachineProfileInfo machine, const ProfileResources& resources)
    : machine_(std::move(machine)), resources_(resources) {
    if (machine_.has_variants) {
        for (const InstCfgFile& file : resources_.variants) {
            if (file.definition() != machine_.id || metaOr(file, "hardware_type") != "nozzle")
                continue;
            if (!variant(file.name()))
                variants_.push_back({file.name(), &file});
        }
    }
    if (variants_.empty())
        variants_.push_back({"empty", nullptr});
    if (machine_.has_materials) {
        for (const MaterialProfile& profile : resources_.materials) {
            for (MaterialContainer& container : materialContainersFor(profile, machine_.id))
                material_containers_.push_back(std::move(container));
        }
    }
}

const VariantEntry* ContainerTree::variant(std::string_view name) const {
    for (const VariantEntry& entry : variants_) {
        if (entry.name == name)
            return &entry;
    }
    return nullptr;
}

std::vector<const MaterialContainer*> ContainerTree::materials(const std::string& variant_name) const {
    // base containers first (registration order of the files), then the machine's, then the variant's
    std::map<std::string, const MaterialContainer*> per_base;
    std::vector<std::string> order;
    for (int pass = 0; pass < 3; ++pass) {
        for (const MaterialContainer& c : material_containers_) {
            const bool wanted = pass == 0   ? c.definition == "fdmprinter"
                                : pass == 1 ? c.definition == machine_.id
                                            : c.definition == machine_.id && c.variant_name == variant_name;
            if (!wanted)
                continue;
            if (!per_base.count(c.profile->base_file))
                order.push_back(c.profile->base_file);
            per_base[c.profile->base_file] = &c;
        }
    }
    std::vector<const MaterialContainer*> result;
    const auto& excluded = machine_.exclude_materials;
    for (const std::string& base : order) {
        const MaterialContainer* c = per_base[base];
        if (std::find(excluded.begin(), excluded.end(), c->id) == excluded.end())
            result.push_back(c);
    }
    return result;
}

std::vector<const InstCfgFile*> ContainerTree::qualitiesWhere(const std::string& definition,
                                                              const std::string* variant,
                                                              const std::string* material) const {
    std::vector<const InstCfgFile*> found;
    for (const InstCfgFile& file : resources_.qualities) {
        if (file.definition() != definition)
            continue;
        const std::string* v = file.meta("variant");
        const std::string* m = file.meta("material");
        if ((variant && (!v || *v != *variant)) || (material && (!m || *m != *material)))
            continue;
        found.push_back(&file);
    }
    return found;
}

std::vector<const InstCfgFile*> ContainerTree::qualities(const std::string& variant_name,
                                                         const MaterialContainer* material) const {
    if (!machine_.has_machine_quality)
        return qualitiesWhere("fdmprinter", nullptr, nullptr);
    if (!machine_.has_materials)
        return qualitiesWhere(machine_.quality_definition, nullptr, nullptr);
    // the empty material has base_file "empty_material" and material type "empty"
    const std::string base_file = material ? material->profile->base_file : "empty_material";
    const std::string material_type = material ? material->profile->material : "empty";
    const std::string* variant = machine_.has_variants ? &variant_name : nullptr;
    std::vector<const InstCfgFile*> found = qualitiesWhere(machine_.quality_definition, variant, &base_file);
    if (!found.empty())
        return found;
    const std::vector<const InstCfgFile*> any_material =
        qualitiesWhere(machine_.quality_definition, variant, nullptr);
    std::set<std::string, std::less<>> same_type;
    for (const MaterialProfile& profile : resources_.materials) {
        if (profile.material == material_type)
            same_type.insert(profile.base_file);
    }
    for (const InstCfgFile* q : any_material) {
        const std::string* m = q->meta("material");
        if (m && same_type.count(*m))
            found.push_back(q);
    }
    if (!found.empty())
        return found;
    for (const InstCfgFile* q : any_material) {
        if (metaOr(*q, "global_quality", "False") != "False")
            found.push_back(q);
    }
    return found;
}

std::vector<std::pair<std::string, const InstCfgFile*>> ContainerTree::globalQualities() const {
    std::vector<std::pair<std::string, const InstCfgFile*>> by_type;
    for (const std::string& definition : {machine_.quality_definition, std::string("fdmprinter")}) {
        for (const InstCfgFile* q : qualitiesWhere(definition, nullptr, nullptr)) {
            const std::string* type = q->meta("quality_type");
            if (metaOr(*q, "global_quality") != "True" || !type)
                continue;
            auto same =
                std::find_if(by_type.begin(), by_type.end(), [&](const auto& e) { return e.first == *type; });
            if (same == by_type.end())
                by_type.emplace_back(*type, q);
            else
                same->second = q;  // MachineNode: global_qualities[quality_type] = node
        }
        if (!by_type.empty())
            break;
    }
    return by_type;
}

std::vector<const InstCfgFile*> ContainerTree::intents(const std::string& variant_name,
                                                       const InstCfgFile& quality) const {
    std::vector<const InstCfgFile*> found;
    const std::string* material = quality.meta("material");
    const std::string* quality_type = quality.meta("quality_type");
    if (!material || !quality_type)
        return found;
    for (const InstCfgFile& file : resources_.intents) {
        if (file.definition() == machine_.quality_definition && metaOr(file, "variant") == variant_name &&
            file.meta("variant") && metaOr(file, "material") == *material && file.meta("material") &&
            metaOr(file, "quality_type") == *quality_type && file.meta("quality_type"))
            found.push_back(&file);
    }
    return found;
}

}  // namespace mixengine
