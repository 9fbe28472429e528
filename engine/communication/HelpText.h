#pragma once
#include <optional>
#include <string>
#include <string_view>

namespace mixengine {

/// The text of `mixengine help`: CuraEngine 4.13's commands and options, plus MixEngine's own.
std::string helpText();

/// The usage of one command (`mixengine <command> --help`, `mixengine help <command>`), or nothing
/// for a name that is not a command.
std::optional<std::string> commandHelp(std::string_view command);

}  // namespace mixengine
