#pragma once
// Setting values between their two forms: the text Cura sends (Python str() of the value) and
// the typed formula::Value that formulas compute with. The setting's definition type decides:
// float → float, int / extruder / optional_extruder → int, bool → bool, polygon(s) and [int] →
// lists, enum / str → str. Text that does not fit its type is an InputError naming the key.
#include <string>
#include <string_view>

#include "settings/formula/Value.h"

namespace mixengine {

formula::Value valueFromText(std::string_view key, std::string_view type, std::string_view text);

/// The value Cura's frontend holds for `text` (Uranium's SettingDefinition type conversion, which
/// keeps Python's literal types): float / int → the literal's own type ("235" → int, "0.4" →
/// float; text that is no number → int 0); bool → True / False, other text stays str ("true");
/// extruder, optional_extruder and [int] → str ("-1" stays the string "-1"); str / enum → str;
/// polygon(s) → lists. Other types as valueFromText.
formula::Value curaValueFromText(std::string_view key, std::string_view type, std::string_view text);

/// Python str() of the value (what Cura would send to its engine).
std::string textFromValue(const formula::Value& value);

}  // namespace mixengine
