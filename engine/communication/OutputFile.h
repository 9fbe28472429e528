#pragma once
// Writing a result file so that a failure never leaves a partial file: the text goes to
// "<path>.tmp-<pid>" first and is renamed over <path> only once complete. Throws InputError
// naming the path when it cannot be written.
#include <filesystem>
#include <string_view>
#include <vector>

namespace mixengine {

void writeFileAtomically(const std::filesystem::path& path, std::string_view text);
/// The same for a text in pieces, written one after the other (no joined copy).
void writeFileAtomically(const std::filesystem::path& path, const std::vector<std::string_view>& pieces);

}  // namespace mixengine
