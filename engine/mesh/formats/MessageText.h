#pragma once
// Wording helpers for one-line warnings and errors of the mesh readers.
#include <cstdint>
#include <string>
#include <string_view>

namespace mixengine {

/// "1 triangle", "3 triangles"; irregular plurals are passed: plural(2, "vertex", "vertices").
inline std::string plural(std::uint64_t n, std::string_view word, std::string_view word_plural = {}) {
    if (n == 1) {
        return "1 " + std::string(word);
    }
    return std::to_string(n) + " " +
           (word_plural.empty() ? std::string(word) + "s" : std::string(word_plural));
}

/// A token quoted for a message, shortened to keep the message on one readable line.
inline std::string quoteToken(std::string_view token) {
    constexpr std::size_t kMax = 40;
    if (token.size() > kMax) {
        return "'" + std::string(token.substr(0, kMax)) + "...'";
    }
    return "'" + std::string(token) + "'";
}

/// `text` with line breaks and tabs turned into spaces, for text from libraries.
inline std::string oneLine(std::string text) {
    for (char& c : text) {
        if (c == '\n' || c == '\r' || c == '\t') {
            c = ' ';
        }
    }
    return text;
}

}  // namespace mixengine
