#pragma once
// Loads the formulas of Cura's setting definitions for the corpus tests, and an Environment that
// answers with the definitions' default values for a single-extruder printer.
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "settings/formula/Formula.h"

namespace mixengine::formula::test {

inline const std::filesystem::path kCuraResources = "/usr/share/cura/resources";

/// The properties of a setting whose string values are Python expressions.
inline const std::vector<std::string> kFormulaProperties = {"value",
                                                            "resolve",
                                                            "enabled",
                                                            "minimum_value",
                                                            "maximum_value",
                                                            "minimum_value_warning",
                                                            "maximum_value_warning"};

struct FormulaSource {
    std::string file;      // e.g. "fdmprinter.def.json"
    std::string key;       // the setting
    std::string property;  // e.g. "value"
    std::string text;      // the formula
};

inline nlohmann::json readJson(const std::filesystem::path& path) {
    std::ifstream in(path);
    return nlohmann::json::parse(in);
}

inline Value jsonToValue(const nlohmann::json& j) {
    if (j.is_null())
        return Value();
    if (j.is_boolean())
        return Value(j.get<bool>());
    if (j.is_number_integer())
        return Value(j.get<std::int64_t>());
    if (j.is_number())
        return Value(j.get<double>());
    if (j.is_string())
        return Value(j.get<std::string>());
    List list;
    if (j.is_array()) {
        for (const auto& item : j)
            list.push_back(jsonToValue(item));
    }
    return Value(std::move(list));
}

inline void addFormulas(const std::string& file, const std::string& key, const nlohmann::json& props,
                        std::vector<FormulaSource>& out) {
    for (const std::string& p : kFormulaProperties) {
        if (props.contains(p) && props[p].is_string())
            out.push_back({file, key, p, props[p].get<std::string>()});
    }
}

/// Walks a definition's nested `settings` / `children` tree: formulas and default values.
inline void walkSettings(const std::string& file, const nlohmann::json& settings,
                         std::vector<FormulaSource>& formulas,
                         std::map<std::string, Value, std::less<>>& defaults) {
    for (const auto& [key, props] : settings.items()) {
        addFormulas(file, key, props, formulas);
        if (props.contains("default_value"))
            defaults[key] = jsonToValue(props["default_value"]);
        if (props.contains("children"))
            walkSettings(file, props["children"], formulas, defaults);
    }
}

/// fdmprinter.def.json and fdmextruder.def.json: their formulas and every setting's default value.
inline void loadBaseDefinitions(std::vector<FormulaSource>& formulas,
                                std::map<std::string, Value, std::less<>>& defaults) {
    for (const char* file : {"fdmprinter.def.json", "fdmextruder.def.json"}) {
        const nlohmann::json def = readJson(kCuraResources / "definitions" / file);
        walkSettings(file, def["settings"], formulas, defaults);
    }
}

/// The formulas in the `overrides` of every machine and extruder definition.
inline std::vector<FormulaSource> loadOverrideFormulas() {
    std::vector<FormulaSource> formulas;
    std::vector<std::filesystem::path> files;
    for (const char* dir : {"definitions", "extruders"}) {
        for (const auto& entry : std::filesystem::directory_iterator(kCuraResources / dir))
            files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    for (const auto& path : files) {
        if (path.extension() != ".json")
            continue;
        const nlohmann::json def = readJson(path);
        if (!def.contains("overrides"))
            continue;
        for (const auto& [key, props] : def["overrides"].items())
            addFormulas(path.filename(), key, props, formulas);
    }
    return formulas;
}

/// Every setting is its default value; Cura's functions answer for one extruder, number 0.
class DefaultsEnvironment : public Environment {
  public:
    explicit DefaultsEnvironment(std::map<std::string, Value, std::less<>> defaults)
        : defaults_(std::move(defaults)) {}

    std::optional<Value> lookup(std::string_view name) const override {
        const auto it = defaults_.find(name);
        if (it == defaults_.end())
            return std::nullopt;
        return it->second;
    }

    std::optional<Value> callFunction(std::string_view name, const std::vector<Value>& args) const override {
        if (name == "defaultExtruderPosition" && args.empty())
            return Value("0");
        // extruderValue(position, key), extruderValueFromContainer(position, key, index)
        if ((name == "extruderValue" && args.size() == 2) ||
            (name == "extruderValueFromContainer" && args.size() == 3)) {
            return defaultOf(args[1]);
        }
        if (name == "extruderValues" && args.size() == 1)
            return Value(List{defaultOf(args[0])});
        // resolveOrValue(key), valueFromContainer(key, index), and Cura 5's anyExtruder* helpers
        if (name == "resolveOrValue" || name == "valueFromContainer" || name == "anyExtruderWithMaterial" ||
            name == "anyExtruderNrWithOrDefault") {
            if (!args.empty())
                return defaultOf(args[0]);
        }
        return std::nullopt;
    }

  private:
    Value defaultOf(const Value& key) const {
        if (!key.is<std::string>())
            throw InputError("setting key expected, got " + toPythonRepr(key));
        const auto it = defaults_.find(key.as<std::string>());
        if (it == defaults_.end())
            throw InputError("unknown setting key " + toPythonRepr(key));
        return it->second;
    }

    std::map<std::string, Value, std::less<>> defaults_;
};

}  // namespace mixengine::formula::test
