#include "settings/FrontendValues.h"

#include <algorithm>
#include <cctype>
#include <ctime>
#include <regex>

#include "common/Error.h"

namespace mixengine {
namespace {

/// Seed 001's colorMode values: 0 single, 1 dual, 2 gradient (the names are accepted as well).
std::string mixingModeOfAlias(const std::string& alias, const std::string& value) {
    static const char* const kModes[] = {"single", "dual", "gradient"};
    for (int i = 0; i < 3; ++i) {
        if (value == kModes[i] || value == std::to_string(i) || value == std::to_string(i) + ".0")
            return kModes[i];
    }
    throw InputError("setting '" + alias + "' (alias of mixing_mode): value '" + value +
                     "' is not 0, 1, 2, single, dual or gradient");
}

std::string withoutComments(const std::string& code) {
    static const std::regex comment(";.+?(\n|$)");
    return std::regex_replace(code, comment, "\n");
}

bool referencesAny(const std::string& code, const std::string& alternatives) {
    const std::regex pattern("\\{(" + alternatives + ")(,\\s?\\w+)?\\}");
    return std::regex_search(withoutComments(code), pattern);
}

std::string formatLocalTime(const char* format) {
    std::time_t now = std::time(nullptr);
    std::tm local{};
    localtime_r(&now, &local);
    char buffer[64];
    std::strftime(buffer, sizeof buffer, format, &local);
    return buffer;
}

SettingValues withValues(const Settings& settings, const SettingValues& changes) {
    SettingValues values = settings.all();
    for (const auto& [key, value] : changes)
        values[key] = value;
    return values;
}

/// `scope` plus what Cura adds to every stack's tokens (StartSliceJob._buildReplacementTokens): the
/// renamed copies of its own values, initial_extruder_nr, and time, date and day. The clock values
/// are not kept in the resolved settings, so that resolution stays reproducible.
Settings withTokenExtras(const Settings& scope, const std::string& initial_extruder_nr) {
    return scope.with(scope.scope(), {{"print_bed_temperature", scope.text(key::material_bed_temperature)},
                                      {"print_temperature", scope.text(key::material_print_temperature)},
                                      {"travel_speed", scope.text(key::speed_travel)},
                                      {"initial_extruder_nr", initial_extruder_nr},
                                      {"time", formatLocalTime("%H:%M:%S")},
                                      {"date", formatLocalTime("%d-%m-%Y")},
                                      {"day", formatLocalTime("%a")}});
}

}  // namespace

std::string expandGcodeTokens(const std::string& code, const Settings& scope,
                              const ResolvedMachine& machine) {
    static const std::regex token("\\{(\\w+)(,\\s?(\\w+))?\\}");
    std::string out;
    auto last = code.cbegin();
    for (std::sregex_iterator it(code.begin(), code.end(), token), end; it != end; ++it) {
        const std::smatch& m = *it;
        out.append(last, m[0].first);
        last = m[0].second;
        const Settings* source = &scope;
        if (m[3].matched) {
            const std::string which = m[3].str();
            if (std::all_of(which.begin(), which.end(), ::isdigit)) {
                const std::size_t nr = std::stoul(which);
                if (nr < machine.extruders.size())
                    source = &machine.extruders[nr];
            } else if (const std::string* nr_value = scope.find(which)) {
                const std::string& nr_text = *nr_value;
                if (!nr_text.empty() && std::all_of(nr_text.begin(), nr_text.end(), ::isdigit) &&
                    std::stoul(nr_text) < machine.extruders.size())
                    source = &machine.extruders[std::stoul(nr_text)];
            }
        }
        const std::string* value = source->find(m[1].str());
        out += value != nullptr ? *value : m[0].str();
    }
    out.append(last, code.cend());
    return out;
}

void applyFrontendValues(ResolvedMachine& machine, const UserSettings& user) {
    const Settings& global = machine.global;
    const std::string start = global.text(key::machine_start_gcode);
    SettingValues changes;
    if (!user.global.count("material_bed_temp_prepend")) {
        const bool referenced =
            referencesAny(start, "material_bed_temperature|material_bed_temperature_layer_0");
        changes["material_bed_temp_prepend"] = referenced ? "False" : "True";
    }
    if (!user.global.count("material_print_temp_prepend")) {
        const bool referenced = referencesAny(start,
                                              "material_print_temperature|material_print_temperature_layer_0|"
                                              "default_material_print_temperature|"
                                              "material_initial_print_temperature|material_final_print_"
                                              "temperature|material_standby_temperature|"
                                              "print_temperature");
        changes["material_print_temp_prepend"] = referenced ? "False" : "True";
    }
    // Cura sends the extruder it starts with (StartSliceJob); the command line does not.
    const std::string initial_nr =
        global.has(key::initial_extruder_nr) ? global.text(key::initial_extruder_nr) : "0";
    const Settings initial = withTokenExtras(machine.extruders.front(), initial_nr);
    changes["machine_start_gcode"] =
        expandGcodeTokens(global.text(key::machine_start_gcode), initial, machine);
    changes["machine_end_gcode"] = expandGcodeTokens(global.text(key::machine_end_gcode), initial, machine);
    changes["print_bed_temperature"] = global.text(key::material_bed_temperature);
    changes["print_temperature"] = global.text(key::material_print_temperature);
    changes["travel_speed"] = global.text(key::speed_travel);
    changes["initial_extruder_nr"] = initial_nr;
    machine.global = Settings(global.scope(), withValues(global, changes));

    for (Settings& extruder : machine.extruders) {
        SettingValues own;
        const Settings tokens = withTokenExtras(extruder, initial_nr);
        own["machine_extruder_start_code"] =
            expandGcodeTokens(extruder.text(key::machine_extruder_start_code), tokens, machine);
        own["machine_extruder_end_code"] =
            expandGcodeTokens(extruder.text(key::machine_extruder_end_code), tokens, machine);
        for (const char* key : {"material_bed_temp_prepend", "material_print_temp_prepend"}) {
            if (auto it = changes.find(key); it != changes.end())
                own[key] = it->second;
        }
        extruder = Settings(extruder.scope(), withValues(extruder, own));
    }
}

SettingValues withCanonicalKeys(const SettingValues& values) {
    static const std::pair<const char*, const char*> kAliases[] = {
        {"colorMode", "mixing_mode"},
        {"colorMixing", "mixing_mode"},
        {"colorA", "mixing_gradient_start"},
        {"colorB", "mixing_gradient_end"},
    };
    SettingValues out = values;
    bool height_alias = false;
    for (const auto& [alias, key] : kAliases) {
        auto it = values.find(alias);
        if (it == values.end())
            continue;
        const std::string value =
            std::string(key) == "mixing_mode" ? mixingModeOfAlias(alias, it->second) : it->second;
        auto [existing, added] = out.emplace(key, value);
        if (!added && existing->second != value) {
            throw InputError("setting '" + std::string(alias) + "' (alias of " + key + ") is '" + it->second +
                             "' but " + key + " is '" + existing->second + "'");
        }
        out.erase(alias);
        height_alias = height_alias || std::string(key) != "mixing_mode";
    }
    if (height_alias)
        out.emplace("mixing_gradient_unit", "percent");
    return out;
}

UserSettings withCanonicalKeys(const UserSettings& user) {
    UserSettings out;
    out.global = withCanonicalKeys(user.global);
    for (const auto& [nr, values] : user.extruders)
        out.extruders[nr] = withCanonicalKeys(values);
    return out;
}

}  // namespace mixengine
