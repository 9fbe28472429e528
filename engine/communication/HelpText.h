#pragma once
#include <string_view>

namespace mixengine {

/// The text of `mixengine help`: CuraEngine 4.13's commands and options, plus MixEngine's own.
std::string_view helpText();

}  // namespace mixengine
