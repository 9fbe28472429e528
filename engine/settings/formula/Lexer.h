#pragma once
// Tokenizer for the Python expressions of setting formulas, internal to the formula code.
//
// Python's lexical rules for an expression: names, keywords (returned as Name tokens), int literals
// (decimal, 0x, 0o, 0b, with `_` separators), float literals (`1.5`, `.5`, `0.`, `1e-3`), string
// literals in ' " ''' """ with an optional r/u prefix and all of Python's escapes, operators, `#`
// comments and `\` line continuations. Newlines inside (), [] and {} are ignored; others become a
// Newline token. Invalid input throws FormulaError naming the formula and the position.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "settings/formula/Value.h"

namespace mixengine::formula {

enum class TokenKind { Name, Number, String, Operator, Newline, End };

struct Token {
    TokenKind kind = TokenKind::End;
    std::string_view text;  ///< the source text of the token (a view into the formula)
    Value literal;          ///< the value of a Number or String token
    std::size_t offset = 0;
};

/// The tokens of `source`, always ending with an End token.
std::vector<Token> tokenize(std::string_view source);

/// "column 7" or "line 2 column 3": the position of `offset` in `source`, for error messages.
std::string describePosition(std::string_view source, std::size_t offset);

}  // namespace mixengine::formula
