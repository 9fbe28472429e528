#pragma once
// Small text-scanning helpers shared by the ASCII STL and OBJ readers.
//
//   parseNumber()  — the whole token must be a decimal number (std::from_chars, so "nan" and
//                    "inf" parse too; callers check finiteness). A leading '+' is accepted.
//   TokenCursor    — walks whitespace-separated tokens of a text, counting lines (1-based) so that
//                    error messages can name the line of the token last returned.
#include <charconv>
#include <cstddef>
#include <string_view>
#include <system_error>

namespace mixengine {

inline bool parseNumber(std::string_view token, double& out) {
    const char* first = token.data();
    const char* last = first + token.size();
    if (first != last && *first == '+') {
        ++first;
    }
    if (first == last) {
        return false;
    }
    const auto result = std::from_chars(first, last, out);
    return result.ec == std::errc() && result.ptr == last;
}

inline bool isBlank(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

/// ASCII case-insensitive comparison of a token with a lower-case keyword.
inline bool sameWord(std::string_view token, std::string_view lower_keyword) {
    if (token.size() != lower_keyword.size()) {
        return false;
    }
    for (std::size_t i = 0; i < token.size(); ++i) {
        const char c = token[i];
        const char lower = (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
        if (lower != lower_keyword[i]) {
            return false;
        }
    }
    return true;
}

class TokenCursor {
  public:
    explicit TokenCursor(std::string_view text) : pos_(text.data()), end_(text.data() + text.size()) {}

    /// The next token, or an empty view at the end of the text.
    std::string_view next() {
        skipSpace();
        const char* start = pos_;
        while (pos_ != end_ && !isBlank(*pos_) && *pos_ != '\n') {
            ++pos_;
        }
        token_line_ = line_;
        return {start, static_cast<std::size_t>(pos_ - start)};
    }

    /// Skips everything up to and including the next newline.
    void skipRestOfLine() {
        while (pos_ != end_ && *pos_ != '\n') {
            ++pos_;
        }
        if (pos_ != end_) {
            ++pos_;
            ++line_;
        }
    }

    /// Line of the token last returned by next().
    std::size_t line() const { return token_line_; }

  private:
    void skipSpace() {
        while (pos_ != end_ && (isBlank(*pos_) || *pos_ == '\n')) {
            if (*pos_ == '\n') {
                ++line_;
            }
            ++pos_;
        }
    }

    const char* pos_;
    const char* end_;
    std::size_t line_ = 1;
    std::size_t token_line_ = 1;
};

}  // namespace mixengine
