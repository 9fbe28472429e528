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

namespace {

/// One --material look-up: the materials of a variant and the filament diameter they must fit.
struct MaterialQuery {
    const std::vector<const MaterialContainer*>& materials;
    int approximate_diameter;
    const std::string& name;
    std::string where;  ///< "machine with variant (extruder n)", for messages

    bool fits(const MaterialContainer* m) const {
        return m && m->profile->approximate_diameter == approximate_diameter;
    }
};

/// Rule 1: the material whose base_file, else whose id, is the name.
const MaterialContainer* byBaseFileOrId(const MaterialQuery& q) {
    if (const MaterialContainer* found = byBaseFile(q.materials, q.name))
        return found;
    for (const MaterialContainer* m : q.materials) {
        if (m->id == q.name)
            return m;
    }
    return nullptr;
}

/// Rule 2: for 1.75 mm filament, "<name>_175" when the name itself does not fit.
const MaterialContainer* byThinFilamentBaseFile(const MaterialQuery& q, const MaterialContainer* found) {
    if (!q.fits(found) && q.approximate_diameter == 2 && q.fits(byBaseFile(q.materials, q.name + "_175")))
        return byBaseFile(q.materials, q.name + "_175");
    return found;
}

/// Rule 3: the one fitting material whose "brand name" or name is the name (case and spaces
/// ignored); two of them are an error.
const MaterialContainer* byDisplayName(const MaterialQuery& q) {
    const std::string key = folded(q.name);
    const MaterialContainer* found = nullptr;
    for (const MaterialContainer* m : q.materials) {
        const MaterialProfile& p = *m->profile;
        if (!q.fits(m) || (folded(p.brand + " " + p.name) != key && folded(p.name) != key))
            continue;
        if (found)
            throw InputError("--material '" + q.name + "': ambiguous for " + q.where + " (" +
                             found->profile->base_file + ", " + p.base_file + ", ...); give a base_file");
        found = m;
    }
    return found;
}

/// The base_files of the fitting materials, generic ones first: they are the ones people look for.
std::vector<std::string> usableMaterials(const MaterialQuery& q) {
    std::vector<std::string> usable;
    for (int generic = 1; generic >= 0; --generic) {
        for (const MaterialContainer* m : q.materials) {
            if (q.fits(m) && (m->profile->brand == "Generic") == (generic == 1))
                usable.push_back(m->profile->base_file);
        }
    }
    return usable;
}

}  // namespace

const MaterialContainer& findMaterial(const ContainerTree& tree, const std::string& variant_name,
                                      int approximate_diameter, const std::string& name, int extruder) {
    const std::vector<const MaterialContainer*> materials = tree.materials(variant_name);
    const MaterialQuery q{materials, approximate_diameter, name,
                          tree.machine().id + (variant_name == "empty" ? "" : " with " + variant_name) +
                              " (extruder " + std::to_string(extruder) + ")"};
    if (materials.empty())
        throw InputError("--material '" + name + "': " + q.where + " has no materials");
    const MaterialContainer* found = byThinFilamentBaseFile(q, byBaseFileOrId(q));
    if (!found)
        found = byDisplayName(q);
    if (!found)
        throw InputError("--material '" + name + "': no such material for " + q.where +
                         "; available: " + shortList(usableMaterials(q)));
    if (!q.fits(found))
        throw InputError("--material '" + name + "': " + found->profile->base_file + " is for " +
                         std::to_string(found->profile->approximate_diameter) + " mm filament but " +
                         q.where + " takes " + std::to_string(approximate_diameter) +
                         " mm (rounded); available: " + shortList(usableMaterials(q)));
    return *found;
}

}  // namespace mixengine
