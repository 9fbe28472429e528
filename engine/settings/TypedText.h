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

/// Python str() of the value (what Cura would send to its engine).
std::string textFromValue(const formula::Value& value);

}  // namespace mixengine
