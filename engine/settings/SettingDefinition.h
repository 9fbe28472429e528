#pragma once
// One setting as a definition file (*.def.json) declares it, after the `inherits` chain and the
// machine's `overrides` have been merged. Values are kept as text, in the form Cura sends them to
// its engine (Python `str()` of the value: `True`, `0.4`, `[[-20, 10], [10, 10]]`).
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace mixengine {

struct SettingDefinition {
    std::string key;
    std::string type;                          ///< "float", "int", "bool", "enum", "str", "polygon", ...
    std::string default_value;                 ///< Python str() of `default_value`
    std::optional<std::string> value_formula;  ///< `value` (a Python expression), if any
    std::optional<std::string> resolve_formula;
    std::optional<std::string> limit_to_extruder;  ///< a Python expression giving an extruder index
    std::optional<std::string> enabled_formula;    ///< `enabled`: whether Cura shows it (a Python expression)
    std::optional<std::string> minimum_value;
    std::optional<std::string> maximum_value;
    std::string unit;
    std::vector<std::string> enum_options;  ///< keys of `options` for enums
    bool settable_per_mesh = true;          // Cura registers both flags with default True
    bool settable_per_extruder = true;
};

using SettingDefinitionMap = std::map<std::string, SettingDefinition, std::less<>>;

}  // namespace mixengine
