#include "settings/formula/Lexer.h"

#include <array>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <optional>

#include "settings/formula/FormulaError.h"
#include "settings/formula/Numeric.h"

namespace mixengine::formula {

namespace {

constexpr std::array<std::string_view, 10> kTwoCharOperators = {
    "**", "//", "<=", ">=", "==", "!=", "<<", ">>", "->", ":="};
constexpr std::string_view kOneCharOperators = "()[]{},.:;+-*/%<>=~&|^@";

bool isDigit(char c) {
    return std::isdigit(static_cast<unsigned char>(c)) != 0;
}
bool isNameStart(char c) {
    return std::isalpha(static_cast<unsigned char>(c)) || c == '_' || (c & 0x80);
}
bool isNameChar(char c) {
    return isNameStart(c) || isDigit(c);
}

void appendUtf8(std::string& out, std::uint32_t cp) {
    if (cp < 0x80) {
        out += static_cast<char>(cp);
    } else if (cp < 0x800) {
        out += static_cast<char>(0xC0 | (cp >> 6));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
        out += static_cast<char>(0xE0 | (cp >> 12));
        out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    } else {
        out += static_cast<char>(0xF0 | (cp >> 18));
        out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
        out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    }
}

/// The character of a one-letter escape ("\\n" → newline, "\\'" → quote), or nullopt.
std::optional<char> simpleEscape(char c) {
    constexpr std::string_view kLetters = "\\'\"abfnrtv";
    constexpr std::string_view kMeanings = "\\'\"\a\b\f\n\r\t\v";
    static_assert(kLetters.size() == kMeanings.size());
    const std::size_t at = kLetters.find(c);
    if (at == std::string_view::npos)
        return std::nullopt;
    return kMeanings[at];
}

class Lexer {
  public:
    explicit Lexer(std::string_view source) : src_(source) {}

    std::vector<Token> run() {
        while (pos_ < src_.size())
            step();
        push(TokenKind::End, pos_, pos_);
        return std::move(tokens_);
    }

  private:
    [[noreturn]] void fail(std::size_t at, const std::string& problem) const {
        throw FormulaError(src_, "invalid syntax at " + describePosition(src_, at) + ": " + problem);
    }

    char peek(std::size_t ahead = 0) const { return pos_ + ahead < src_.size() ? src_[pos_ + ahead] : '\0'; }

    void push(TokenKind kind, std::size_t begin, std::size_t end, Value literal = Value()) {
        tokens_.push_back(Token{kind, src_.substr(begin, end - begin), std::move(literal), begin});
    }

    void step() {
        const char c = peek();
        if (c == ' ' || c == '\t' || c == '\f' || c == '\r') {
            ++pos_;
        } else if (c == '\n') {
            if (depth_ == 0 && (tokens_.empty() || tokens_.back().kind != TokenKind::Newline)) {
                push(TokenKind::Newline, pos_, pos_ + 1);
            }
            ++pos_;
        } else if (c == '#') {
            while (pos_ < src_.size() && src_[pos_] != '\n')
                ++pos_;
        } else if (c == '\\') {
            lineContinuation();
        } else if (isDigit(c) || (c == '.' && isDigit(peek(1)))) {
            number();
        } else if (c == '\'' || c == '"') {
            string(pos_, false);
        } else if (isNameStart(c)) {
            nameOrPrefixedString();
        } else {
            punctuation();
        }
    }

    void lineContinuation() {
        std::size_t next = pos_ + 1;
        if (next < src_.size() && src_[next] == '\r')
            ++next;
        if (next >= src_.size() || src_[next] != '\n')
            fail(pos_, "unexpected character after line continuation");
        pos_ = next + 1;
    }

    void punctuation() {
        const std::string_view two = src_.substr(pos_, 2);
        for (const std::string_view op : kTwoCharOperators) {
            if (two == op) {
                push(TokenKind::Operator, pos_, pos_ + 2);
                pos_ += 2;
                return;
            }
        }
        const char c = peek();
        if (kOneCharOperators.find(c) == std::string_view::npos) {
            fail(pos_, "unexpected character '" + std::string(1, c) + "'");
        }
        if (c == '(' || c == '[' || c == '{')
            ++depth_;
        if ((c == ')' || c == ']' || c == '}') && depth_ > 0)
            --depth_;
        push(TokenKind::Operator, pos_, pos_ + 1);
        ++pos_;
    }

    void nameOrPrefixedString() {
        const std::size_t begin = pos_;
        while (pos_ < src_.size() && isNameChar(src_[pos_]))
            ++pos_;
        const std::string_view word = src_.substr(begin, pos_ - begin);
        const char next = peek();
        if ((next == '\'' || next == '"') && word.size() <= 2) {
            bool raw = false;
            for (const char p : word) {
                const char lower = static_cast<char>(std::tolower(static_cast<unsigned char>(p)));
                if (lower == 'b' || lower == 'f')
                    fail(begin, "bytes and f-string literals are not supported");
                if (lower != 'r' && lower != 'u')
                    fail(begin, "unknown string prefix '" + std::string(word) + "'");
                raw = raw || lower == 'r';
            }
            string(begin, raw);
            return;
        }
        push(TokenKind::Name, begin, pos_);
    }

    void digits(bool (*accept)(char)) {
        while (pos_ < src_.size() && (accept(src_[pos_]) || (src_[pos_] == '_' && accept(peek(1))))) {
            pos_ += src_[pos_] == '_' ? 2 : 1;
        }
    }

    void number() {
        const std::size_t begin = pos_;
        if (const int base = radixPrefixBase()) {
            radixInteger(begin, base);
            return;
        }
        const bool isFloat = decimalDigits();
        if (peek() == 'j' || peek() == 'J')
            fail(begin, "imaginary numbers are not supported");
        const std::string_view text = src_.substr(begin, pos_ - begin);
        if (isFloat) {
            floatLiteral(begin, text);
        } else {
            decimalInteger(begin, text);
        }
    }

    /// 16, 8 or 2 when a "0x", "0o" or "0b" prefix (any case) starts here, else 0.
    int radixPrefixBase() const {
        if (peek() != '0')
            return 0;
        const char radix = static_cast<char>(std::tolower(static_cast<unsigned char>(peek(1))));
        return radix == 'x' ? 16 : radix == 'o' ? 8 : radix == 'b' ? 2 : 0;
    }

    /// Scans the digits, fraction and exponent of a decimal literal; true if it is a float.
    bool decimalDigits() {
        digits(isDigit);
        bool isFloat = false;
        if (peek() == '.') {
            isFloat = true;
            ++pos_;
            digits(isDigit);
        }
        const bool hasExponent = exponent();
        return isFloat || hasExponent;
    }

    /// Scans "e5", "E-3", ... if one starts here; false (nothing scanned) otherwise.
    bool exponent() {
        const char sign = peek(1);
        if (peek() != 'e' && peek() != 'E')
            return false;
        if (!isDigit(sign) && !((sign == '+' || sign == '-') && isDigit(peek(2))))
            return false;
        pos_ += isDigit(sign) ? 1 : 2;
        digits(isDigit);
        return true;
    }

    void floatLiteral(std::size_t begin, std::string_view text) {
        try {  // e.g. "0._0": the digit scan allows underscores that Python rejects there
            push(TokenKind::Number, begin, pos_, Value(parseFloatString(text)));
        } catch (const detail::EvalProblem&) {
            fail(begin, "invalid decimal literal " + std::string(text));
        }
    }

    void decimalInteger(std::size_t begin, std::string_view text) {
        if (text.size() > 1 && text[0] == '0' && text.find_first_not_of("0_") != std::string_view::npos) {
            fail(begin, "leading zeros in decimal integer literals are not permitted");
        }
        try {
            push(TokenKind::Number, begin, pos_, Value(parseIntString(text)));
        } catch (const detail::EvalProblem&) {
            fail(begin, "integer literal " + std::string(text) + " does not fit in 64 bits");
        }
    }

    void radixInteger(std::size_t begin, int base) {
        pos_ += 2;
        std::string plain;
        while (pos_ < src_.size() &&
               (std::isalnum(static_cast<unsigned char>(src_[pos_])) || src_[pos_] == '_')) {
            if (src_[pos_] != '_')
                plain += src_[pos_];
            ++pos_;
        }
        std::int64_t value = 0;
        const auto res = std::from_chars(plain.data(), plain.data() + plain.size(), value, base);
        if (plain.empty() || res.ptr != plain.data() + plain.size() || res.ec != std::errc()) {
            fail(begin, "invalid integer literal '" + std::string(src_.substr(begin, pos_ - begin)) + "'");
        }
        push(TokenKind::Number, begin, pos_, Value(value));
    }

    void string(std::size_t begin, bool raw) {
        const char quote = peek();
        const bool triple = peek(1) == quote && peek(2) == quote;
        pos_ += triple ? 3 : 1;
        std::string value;
        while (true) {
            if (pos_ >= src_.size())
                fail(begin, "unterminated string literal");
            const char c = src_[pos_];
            if (c == quote && (!triple || (peek(1) == quote && peek(2) == quote))) {
                pos_ += triple ? 3 : 1;
                break;
            }
            if (c == '\n' && !triple)
                fail(begin, "unterminated string literal");
            if (c == '\\') {
                escape(value, raw);
            } else {
                value += c;
                ++pos_;
            }
        }
        push(TokenKind::String, begin, pos_, Value(std::move(value)));
    }

    std::uint32_t hexDigits(std::size_t count) {
        std::uint32_t cp = 0;
        const std::string_view hex = src_.substr(pos_, count);
        const auto res = std::from_chars(hex.data(), hex.data() + hex.size(), cp, 16);
        if (hex.size() != count || res.ptr != hex.data() + hex.size())
            fail(pos_, "truncated \\x, \\u or \\U escape");
        pos_ += count;
        return cp;
    }

    void escape(std::string& out, bool raw) {
        const std::size_t at = pos_;
        const char c = peek(1);
        if (raw) {
            rawEscape(out, c);
            return;
        }
        pos_ += 2;
        if (c == '\n')
            return;  // a line continuation inside the string
        if (const std::optional<char> simple = simpleEscape(c)) {
            out += *simple;
        } else if (c == 'x' || c == 'u' || c == 'U') {
            hexEscape(out, c, at);
        } else if (c >= '0' && c <= '7') {
            octalEscape(out, c);
        } else if (c == 'N') {
            fail(at, "\\N{...} escapes are not supported");
        } else if (c == '\0') {
            fail(at, "unterminated string literal");
        } else {
            out += '\\';  // Python keeps unknown escapes such as "\d" as they are
            out += c;
        }
    }

    /// A raw string keeps the backslash; it only stops the next character ending the string.
    void rawEscape(std::string& out, char c) {
        out += '\\';
        if (c != '\0')
            out += c;
        pos_ += c == '\0' ? 1 : 2;
    }

    /// \xhh, \uhhhh, \Uhhhhhhhh (`kind` is x, u or U); `at` is the backslash, for messages.
    void hexEscape(std::string& out, char kind, std::size_t at) {
        const std::uint32_t cp = hexDigits(kind == 'x' ? 2 : kind == 'u' ? 4 : 8);
        if (cp > 0x10FFFF)
            fail(at, "\\U escape out of range");
        appendUtf8(out, cp);
    }

    /// \o, \oo or \ooo: `first` is the first octal digit, already consumed.
    void octalEscape(std::string& out, char first) {
        std::uint32_t cp = static_cast<std::uint32_t>(first - '0');
        for (int i = 0; i < 2 && peek() >= '0' && peek() <= '7'; ++i, ++pos_)
            cp = cp * 8 + (peek() - '0');
        appendUtf8(out, cp);
    }

    std::string_view src_;
    std::size_t pos_ = 0;
    int depth_ = 0;
    std::vector<Token> tokens_;
};

}  // namespace

std::vector<Token> tokenize(std::string_view source) {
    return Lexer(source).run();
}

std::string describePosition(std::string_view source, std::size_t offset) {
    std::size_t line = 1;
    std::size_t lineStart = 0;
    for (std::size_t i = 0; i < offset && i < source.size(); ++i) {
        if (source[i] == '\n') {
            ++line;
            lineStart = i + 1;
        }
    }
    const std::string column = "column " + std::to_string(offset - lineStart + 1);
    return line == 1 ? column : "line " + std::to_string(line) + " " + column;
}

}  // namespace mixengine::formula
