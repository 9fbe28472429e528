#include "settings/profiles/ProfileNames.h"

#include <cctype>

#include "common/Error.h"

namespace mixengine {
namespace {

/// Lower case without white space: "AA 0.4" → "aa0.4".
std::string folded(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (!std::isspace(static_cast<unsigned char>(c)))
            out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    return out;
}

std::string trimmed(const std::string& text) {
    std::size_t a = 0, b = text.size();
    while (a < b && std::isspace(static_cast<unsigned char>(text[a])))
        ++a;
    while (b > a && std::isspace(static_cast<unsigned char>(text[b - 1])))
        --b;
    return text.substr(a, b - a);
}

std::vector<std::string> variantNames(const ContainerTree& tree) {
    std::vector<std::string> names;
    for (const VariantEntry& v : tree.variants())
        names.push_back(v.name);
    return names;
}

const MaterialContainer* byBaseFile(const std::vector<const MaterialContainer*>& materials,
                                    const std::string& base) {
    for (const MaterialContainer* m : materials) {
        if (m->profile->base_file == base)
            return m;
    }
    return nullptr;
}

}  // namespace

std::vector<std::string> namesPerExtruder(const std::string& names, int extruder_count, const char* option) {
    std::vector<std::string> parts;
    std::size_t start = 0;
    for (;;) {
        std::size_t comma = names.find(',', start);
        parts.push_back(
            trimmed(names.substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
        if (comma == std::string::npos)
            break;
        start = comma + 1;
    }
    if (parts.size() == 1)
        return std::vector<std::string>(static_cast<std::size_t>(extruder_count), parts.front());
    if (parts.size() > static_cast<std::size_t>(extruder_count))
        throw InputError(std::string(option) + " '" + names + "': " + std::to_string(parts.size()) +
                         " names for " + std::to_string(extruder_count) + " extruder(s)");
    parts.resize(static_cast<std::size_t>(extruder_count));
    return parts;
}

std::string shortList(const std::vector<std::string>& names, std::size_t limit) {
    if (names.empty())
        return "(none)";
    std::string out;
    for (std::size_t i = 0; i < names.size() && i < limit; ++i)
        out += (i ? ", " : "") + names[i];
    if (names.size() > limit)
        out += ", ... (" + std::to_string(names.size() - limit) + " more)";
    return out;
}

const VariantEntry& findVariant(const ContainerTree& tree, const std::string& name) {
    const std::string& machine = tree.machine().id;
    if (!tree.machine().has_variants || !tree.variants().front().file) {
        if (name == "empty")
            return tree.variants().front();
        throw InputError("--variant '" + name + "': " + machine + " has no nozzle variants");
    }
    for (const VariantEntry& v : tree.variants()) {
        if (v.name == name || v.file->id == name)
            return v;
    }
    const std::string key = folded(name);
    const VariantEntry* prefix = nullptr;
    int prefix_count = 0;
    for (const VariantEntry& v : tree.variants()) {
        if (folded(v.name) == key)
            return v;
        if (!key.empty() && folded(v.name).rfind(key, 0) == 0) {
            prefix = &v;
            ++prefix_count;
        }
    }
    if (prefix_count == 1)
        return *prefix;
    throw InputError("--variant '" + name + "': " + (prefix_count > 1 ? "ambiguous" : "no such variant") +
                     " for " + machine + "; available: " + shortList(variantNames(tree)));
}

const MaterialContainer& findMaterial(const ContainerTree& tree, const std::string& variant_name,
                                      int approximate_diameter, const std::string& name, int extruder) {
    const std::vector<const MaterialContainer*> materials = tree.materials(variant_name);
    const std::string where = tree.machine().id + (variant_name == "empty" ? "" : " with " + variant_name) +
                              " (extruder " + std::to_string(extruder) + ")";
    if (materials.empty())
        throw InputError("--material '" + name + "': " + where + " has no materials");
    auto fits = [&](const MaterialContainer* m) {
        return m && m->profile->approximate_diameter == approximate_diameter;
    };

    const MaterialContainer* found = byBaseFile(materials, name);
    for (const MaterialContainer* m : materials) {
        if (!found && m->id == name)
            found = m;
    }
    if (!fits(found) && approximate_diameter == 2 && fits(byBaseFile(materials, name + "_175")))
        found = byBaseFile(materials, name + "_175");
    if (!found) {
        const std::string key = folded(name);
        for (const MaterialContainer* m : materials) {
            const MaterialProfile& p = *m->profile;
            if (fits(m) && (folded(p.brand + " " + p.name) == key || folded(p.name) == key)) {
                if (found)
                    throw InputError("--material '" + name + "': ambiguous for " + where + " (" +
                                     found->profile->base_file + ", " + p.base_file +
                                     ", ...); give a base_file");
                found = m;
            }
        }
    }
    std::vector<std::string> usable;  // generic materials first: they are the ones people look for
    for (int generic = 1; generic >= 0; --generic) {
        for (const MaterialContainer* m : materials) {
            if (fits(m) && (m->profile->brand == "Generic") == (generic == 1))
                usable.push_back(m->profile->base_file);
        }
    }
    if (!found)
        throw InputError("--material '" + name + "': no such material for " + where +
                         "; available: " + shortList(usable));
    if (!fits(found))
        throw InputError("--material '" + name + "': " + found->profile->base_file + " is for " +
                         std::to_string(found->profile->approximate_diameter) + " mm filament but " + where +
                         " takes " + std::to_string(approximate_diameter) +
                         " mm (rounded); available: " + shortList(usable));
    return *found;
}

}  // namespace mixengine
