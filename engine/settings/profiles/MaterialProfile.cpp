#include "settings/profiles/MaterialProfile.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>

#include "common/Error.h"
#include "common/TextFile.h"
#include "settings/JsonText.h"
#include "settings/profiles/XmlScan.h"

namespace mixengine {
namespace {

constexpr std::string_view kUm = "http://www.ultimaker.com/material";
constexpr std::string_view kCura = "http://www.ultimaker.com/cura";

/// XmlMaterialProfile's __material_settings_setting_map.
const std::map<std::string_view, std::string_view>& settingMap() {
    static const std::map<std::string_view, std::string_view> kMap = {
        {"print temperature", "default_material_print_temperature"},
        {"heated bed temperature", "default_material_bed_temperature"},
        {"standby temperature", "material_standby_temperature"},
        {"processing temperature graph", "material_flow_temp_graph"},
        {"print cooling", "cool_fan_speed"},
        {"retraction amount", "retraction_amount"},
        {"retraction speed", "retraction_speed"},
        {"adhesion tendency", "material_adhesion_tendency"},
        {"surface energy", "material_surface_energy"},
        {"build volume temperature", "build_volume_temperature"},
        {"anti ooze retract position", "material_anti_ooze_retracted_position"},
        {"anti ooze retract speed", "material_anti_ooze_retraction_speed"},
        {"break preparation position", "material_break_preparation_retracted_position"},
        {"break preparation speed", "material_break_preparation_speed"},
        {"break preparation temperature", "material_break_preparation_temperature"},
        {"break position", "material_break_retracted_position"},
        {"flush purge speed", "material_flush_purge_speed"},
        {"flush purge length", "material_flush_purge_length"},
        {"end of filament purge speed", "material_end_of_filament_purge_speed"},
        {"end of filament purge length", "material_end_of_filament_purge_length"},
        {"maximum park duration", "material_maximum_park_duration"},
        {"no load move factor", "material_no_load_move_factor"},
        {"break speed", "material_break_speed"},
        {"break temperature", "material_break_temperature"},
    };
    return kMap;
}

/// The plugin's product_to_id.json.
const std::map<std::string_view, std::string_view>& productMap() {
    static const std::map<std::string_view, std::string_view> kMap = {
        {"Ultimaker 2", "ultimaker2"},
        {"Ultimaker 2 Extended", "ultimaker2_extended"},
        {"Ultimaker 2 Extended+", "ultimaker2_extended_plus"},
        {"Ultimaker 2 Go", "ultimaker2_go"},
        {"Ultimaker 2+", "ultimaker2_plus"},
        {"Ultimaker 2+ Connect", "ultimaker2_plus_connect"},
        {"Ultimaker 3", "ultimaker3"},
        {"Ultimaker 3 Extended", "ultimaker3_extended"},
        {"Ultimaker S3", "ultimaker_s3"},
        {"Ultimaker S5", "ultimaker_s5"},
        {"Ultimaker Original", "ultimaker_original"},
        {"Ultimaker Original+", "ultimaker_original_plus"},
        {"Ultimaker Original Dual Extrusion", "ultimaker_original_dual"},
        {"IMADE3D JellyBOX", "imade3d_jellybox"},
    };
    return kMap;
}

bool parseCompatible(const std::string& text) {
    return text == "yes" || text == "unknown";
}

std::string lower(std::string text) {
    for (char& c : text)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return text;
}

std::optional<double> pythonFloat(const std::string& text) {
    std::size_t a = 0, b = text.size();
    while (a < b && std::isspace(static_cast<unsigned char>(text[a])))
        ++a;
    while (b > a && std::isspace(static_cast<unsigned char>(text[b - 1])))
        --b;
    const std::string trimmed = text.substr(a, b - a);
    char* end = nullptr;
    const double v = std::strtod(trimmed.c_str(), &end);
    if (trimmed.empty() || end != trimmed.c_str() + trimmed.size())
        return std::nullopt;
    return v;
}

std::string graphText(const XmlElement& setting, const std::string& source) {
    std::string out = "[";
    for (const XmlElement* point : setting.childrenNamed(kUm, "point")) {
        const std::string* flow = point->attribute("flow");
        const std::string* temperature = point->attribute("temperature");
        std::optional<double> f = flow ? pythonFloat(*flow) : std::nullopt;
        std::optional<double> t = temperature ? pythonFloat(*temperature) : std::nullopt;
        if (!f || !t)
            throw InputError(source +
                             ": processing temperature graph: a <point> needs numeric flow and temperature");
        if (out.size() > 1)
            out += ", ";
        out += "[" + pythonFloatText(*f) + ", " + pythonFloatText(*t) + "]";
    }
    return out + "]";
}

/// The <setting> and <cura:setting> children of `node`: mapped values into `values`, the
/// "hardware compatible" flag into `compatible` (left alone when absent).
void readSettings(const XmlElement& node, MaterialValues& values, bool& compatible,
                  const std::string& source) {
    for (const XmlElement* setting : node.childrenNamed(kUm, "setting")) {
        const std::string* key = setting->attribute("key");
        if (!key)
            continue;
        if (auto it = settingMap().find(*key); it != settingMap().end()) {
            values[std::string(it->second)] =
                *key == "processing temperature graph" ? graphText(*setting, source) : setting->text;
        } else if (*key == "hardware compatible") {
            compatible = parseCompatible(setting->text);
        }
    }
    for (const XmlElement* setting : node.childrenNamed(kCura, "setting")) {
        const std::string* key = setting->attribute("key");
        if (!key)
            continue;
        const std::string folded = lower(setting->text);
        values[*key] = folded == "yes" ? "True" : folded == "no" ? "False" : setting->text;
    }
}

void readMetadata(const XmlElement& root, MaterialProfile& profile) {
    profile.name = "Unknown Material";
    const XmlElement* metadata = root.child(kUm, "metadata");
    if (!metadata)
        return;
    for (const XmlElement& entry : metadata->children) {
        if (entry.name == "name") {
            auto text = [&](std::string_view tag, const char* fallback) {
                const XmlElement* e = entry.child(kUm, tag);
                return e && !e->text.empty() ? e->text : std::string(fallback);
            };
            const XmlElement* label = entry.child(kUm, "label");
            profile.brand = text("brand", "Unknown Brand");
            profile.material = text("material", "Unknown Type");
            profile.color_name = text("color", "Unknown Color");
            if (label && !label->text.empty())
                profile.name = label->text;
            else if (entry.child(kUm, "material"))
                profile.name = profile.color_name == "Generic" ? profile.material
                                                               : profile.color_name + " " + profile.material;
        } else if (entry.name != "setting_version") {
            profile.metadata[entry.name] = entry.text;
        }
    }
    if (auto it = profile.metadata.find("GUID"); it != profile.metadata.end()) {
        profile.guid = it->second;
        profile.values["material_guid"] = it->second;
    }
}

MaterialMachineBlock readMachine(const XmlElement& machine, bool common_compatible,
                                 const std::string& source) {
    MaterialMachineBlock block;
    block.compatible = common_compatible;
    for (const XmlElement* identifier : machine.childrenNamed(kUm, "machine_identifier")) {
        if (const std::string* product = identifier->attribute("product"))
            block.products.push_back(*product);
    }
    readSettings(machine, block.values, block.compatible, source);
    for (const XmlElement* hotend : machine.childrenNamed(kUm, "hotend")) {
        const std::string* id = hotend->attribute("id");
        if (!id)
            continue;
        MaterialHotend h;
        h.name = *id;
        h.compatible = block.compatible;
        readSettings(*hotend, h.values, h.compatible, source);
        block.hotends.push_back(std::move(h));
    }
    return block;
}

}  // namespace

MaterialProfile parseMaterialProfile(std::string_view text, std::string base_file, std::string source) {
    const XmlElement root = parseXml(text, source);
    if (root.ns != kUm || root.name != "fdmmaterial")
        throw InputError(source + ": not a material profile (root element is <" + root.name + ">)");
    MaterialProfile profile;
    profile.base_file = std::move(base_file);
    profile.source = std::move(source);
    readMetadata(root, profile);

    std::string diameter = "2.85";
    if (const XmlElement* properties = root.child(kUm, "properties")) {
        if (const XmlElement* d = properties->child(kUm, "diameter")) {
            diameter = d->text;
            profile.values["material_diameter"] = d->text;
        }
    }
    std::optional<double> d = pythonFloat(diameter);
    if (!d)
        throw InputError(profile.source + ": properties/diameter '" + diameter + "' is not a number");
    profile.approximate_diameter = static_cast<int>(std::nearbyint(*d));

    if (const XmlElement* settings = root.child(kUm, "settings")) {
        readSettings(*settings, profile.values, profile.compatible, profile.source);
        for (const XmlElement* machine : settings->childrenNamed(kUm, "machine"))
            profile.machines.push_back(readMachine(*machine, profile.compatible, profile.source));
    }
    return profile;
}

MaterialProfile readMaterialFile(const std::filesystem::path& path) {
    const std::string text = readTextFile(path);
    std::string name = path.filename().string();
    if (name.ends_with(".xml.fdm_material"))
        name.resize(name.size() - 17);
    return parseMaterialProfile(text, name, path.string());
}

std::vector<std::string> productDefinitionIds(const std::string& product) {
    if (auto it = productMap().find(product); it != productMap().end())
        return {std::string(it->second)};
    const std::string folded = lower(product);
    std::vector<std::string> merged;
    std::istringstream words(folded);
    for (std::string part; std::getline(words, part, ' ');) {
        if (part.empty())
            continue;
        const bool digits = part.find_first_not_of("0123456789") == std::string::npos;
        if (!merged.empty() && digits)
            merged.back() += part;
        else
            merged.push_back(part);
    }
    std::string without_spaces, underscored = folded, joined;
    for (char c : folded) {
        if (c != ' ')
            without_spaces += c;
    }
    for (char& c : underscored) {
        if (c == ' ')
            c = '_';
    }
    for (const std::string& part : merged)
        joined += (joined.empty() ? "" : "_") + part;
    std::vector<std::string> ids = {without_spaces};
    for (const std::string& id : {underscored, joined}) {
        if (std::find(ids.begin(), ids.end(), id) == ids.end())
            ids.push_back(id);
    }
    return ids;
}

std::vector<MaterialContainer> materialContainersFor(const MaterialProfile& profile,
                                                     const std::string& machine_id) {
    std::vector<MaterialContainer> out;
    out.push_back({profile.base_file, "fdmprinter", "", profile.compatible, &profile, profile.values});
    for (const MaterialMachineBlock& block : profile.machines) {
        for (const std::string& product : block.products) {
            const std::vector<std::string> ids = productDefinitionIds(product);
            if (std::find(ids.begin(), ids.end(), machine_id) == ids.end())
                continue;
            MaterialValues machine_values = profile.values;
            for (const auto& [key, value] : block.values)
                machine_values[key] = value;
            const std::string machine_container = profile.base_file + "_" + machine_id;
            out.push_back({machine_container, machine_id, "", block.compatible, &profile, machine_values});
            for (const MaterialHotend& hotend : block.hotends) {
                MaterialValues hotend_values = machine_values;
                for (const auto& [key, value] : hotend.values)
                    hotend_values[key] = value;
                std::string suffix = hotend.name;
                std::replace(suffix.begin(), suffix.end(), ' ', '_');
                out.push_back({machine_container + "_" + suffix, machine_id, hotend.name, hotend.compatible,
                               &profile, std::move(hotend_values)});
            }
        }
    }
    return out;
}

}  // namespace mixengine
