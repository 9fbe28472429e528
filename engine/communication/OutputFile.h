#pragma once
// Writing a result file so that a failure never leaves a partial file: the text goes to
// "<path>.tmp-<pid>" first and is renamed over <path> only once complete. Throws InputError
// naming the path when it cannot be written.
#include <filesystem>
#include <string_view>

namespace mixengine {

void writeFileAtomically(const std::filesystem::path& path, std::string_view text);

}  // namespace mixengine
