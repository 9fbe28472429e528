#include "settings/profiles/ProfileSelector.h"

#include "common/Error.h"
#include "settings/profiles/CuraSession.h"
#include "settings/profiles/ProfileNames.h"

namespace mixengine {
namespace {

/// Values of keys the machine defines, as stack values (a leading '=' makes a formula).
template <typename Pairs>
std::map<std::string, ContainerValue, std::less<>> knownValues(const DefinitionSet& definitions,
                                                               const Pairs& pairs) {
    std::map<std::string, ContainerValue, std::less<>> values;
    for (const auto& [key, text] : pairs) {
        if (definitions.find(key))
            values[key] = containerValueFromText(text);
    }
    return values;
}

void push(std::vector<InstanceContainer>& stack, const DefinitionSet& definitions, const InstCfgFile* file,
          const char* type) {
    if (file)
        stack.push_back({file->id, type, knownValues(definitions, file->values)});
}

ProfileStack toStack(const DefinitionSet& definitions, const CuraSession& session) {
    ProfileStack stack;
    stack.cura = true;
    push(stack.global, definitions, session.globalQuality(), "quality");
    const std::vector<ExtruderChoice>& extruders = session.extruders();
    for (std::size_t position = 0; position < extruders.size(); ++position) {
        const ExtruderChoice& e = extruders[position];
        std::vector<InstanceContainer>& containers = stack.extruders[static_cast<int>(position)];
        push(containers, definitions, e.intent, "intent");
        push(containers, definitions, e.quality, "quality");
        if (e.material)
            containers.push_back({e.material->id, "material", knownValues(definitions, e.material->values)});
        push(containers, definitions, e.variant->file, "variant");
    }
    return stack;
}

/// An intent container id → its category and quality type; a category stays as it is.
std::pair<std::string, std::string> intentByName(const ContainerTree& tree, const ProfileResources& resources,
                                                 const std::string& name) {
    for (const InstCfgFile& intent : resources.intents) {
        if (intent.id == name && intent.definition() == tree.machine().quality_definition)
            return {intentCategory(&intent), metaOr(intent, "quality_type")};
    }
    return {name, ""};
}

void selectQuality(CuraSession& session, const std::string& name) {
    try {
        session.setQualityType(name);
    } catch (const InputError&) {
        const std::string type = session.qualityTypeOfId(name);
        if (type.empty())
            throw;
        session.setQualityType(type);
    }
}

}  // namespace

ProfileStack selectProfiles(const DefinitionSet& definitions, const ProfileSelection& selection,
                            const ProfileResources& resources) {
    const ContainerTree tree(machineProfileInfo(definitions), resources);
    CuraSession session(definitions, tree);
    const int count = static_cast<int>(session.extruders().size());

    const std::vector<std::string> variants = namesPerExtruder(selection.variant, count, "--variant");
    for (int i = 0; i < count; ++i) {
        if (!variants[static_cast<std::size_t>(i)].empty())
            session.setVariant(i, findVariant(tree, variants[static_cast<std::size_t>(i)]));
    }
    const std::vector<std::string> materials = namesPerExtruder(selection.material, count, "--material");
    for (int i = 0; i < count; ++i) {
        const std::string& name = materials[static_cast<std::size_t>(i)];
        if (name.empty())
            continue;
        const VariantEntry& variant = *session.extruders()[static_cast<std::size_t>(i)].variant;
        session.setMaterial(
            i, findMaterial(tree, variant.name, session.approximateDiameter(i, &variant), name, i));
    }
    const auto [category, intent_quality] = intentByName(tree, resources, selection.intent);
    if (!selection.quality.empty()) {
        selectQuality(session, selection.quality);
        const InstCfgFile* global = session.globalQuality();
        if (!intent_quality.empty() && (!global || metaOr(*global, "quality_type") != intent_quality))
            throw InputError("--intent '" + selection.intent + "' is made for quality '" + intent_quality +
                             "', not '" + selection.quality + "'");
    } else if (!intent_quality.empty()) {
        selectQuality(session, intent_quality);
    }
    if (!category.empty())
        session.setIntentCategory(category);
    return toStack(definitions, session);
}

ProfileStack selectProfiles(const DefinitionSet& definitions, const ProfileSelection& selection,
                            const std::vector<std::filesystem::path>& search_path) {
    const MachineProfileInfo machine = machineProfileInfo(definitions);
    const std::vector<std::filesystem::path> roots = profileRoots(search_path);
    if (roots.empty())
        throw InputError(
            "profiles requested, but no Cura resources (variants/, quality/, intent/, materials/) "
            "were found next to the definition search path");
    const ProfileResources resources =
        loadProfileResources(roots, {machine.id, machine.quality_definition, std::string("fdmprinter")});
    return selectProfiles(definitions, selection, resources);
}

}  // namespace mixengine
