#pragma once
// Small text-file helpers shared by the readers of Cura's resource files.
#include <filesystem>
#include <string>
#include <string_view>

namespace mixengine {

/// The whole file as bytes; throws InputError "<path>: cannot read the file".
std::string readTextFile(const std::filesystem::path& path);

/// "\r\n" and lone "\r" become "\n".
std::string normaliseLineEnds(std::string_view text);

}  // namespace mixengine
