// Recursive-descent parser for the Python expression grammar of setting formulas (see Formula.h).
// Names are resolved while parsing: comprehension variables to slots, built-ins and math members
// to constants, everything else to setting keys. A comprehension's element is written before its
// `for` clauses, so a bracket's tokens are first scanned for a `for` at its own level; when there is
// one, the clauses are parsed first (binding their variables) and then the element, once. (Parsing
// the element twice, once to find its end, took time exponential in the nesting of comprehensions.)
#include <algorithm>
#include <array>

#include "settings/formula/Builtins.h"
#include "settings/formula/Formula.h"
#include "settings/formula/Lexer.h"
#include "settings/formula/ParserState.h"

namespace mixengine::formula {

namespace {

using detail::BinaryOp;
using detail::ClauseKind;
using detail::CompareOp;
using detail::Node;
using detail::NodeKind;
using detail::UnaryOp;

constexpr std::array<std::string_view, 35> kKeywords = {
    "False", "None",     "True",  "and",    "as",   "assert", "async",  "await",    "break",
    "class", "continue", "def",   "del",    "elif", "else",   "except", "finally",  "for",
    "from",  "global",   "if",    "import", "in",   "is",     "lambda", "nonlocal", "not",
    "or",    "pass",     "raise", "return", "try",  "while",  "with",   "yield"};

bool isKeyword(std::string_view word) {
    return std::find(kKeywords.begin(), kKeywords.end(), word) != kKeywords.end();
}

class Parser : public ParserState {
  public:
    using ParserState::ParserState;

    Expression run() {
        skipNewlines();
        std::uint32_t root = parseTest();
        if (isOp(","))
            root = parseTupleTail(root, "");
        skipNewlines();
        if (peek().kind != TokenKind::End)
            unexpected();
        return finish(root);
    }

  private:
    void skipNewlines() {
        while (peek().kind == TokenKind::Newline)
            ++pos_;
    }

    std::uint32_t parseTest() {
        const DepthGuard guard(*this);
        if (isName("lambda"))
            fail(peek(), "lambda expressions are not supported");
        const std::uint32_t value = parseOr();
        if (!isName("if"))
            return value;
        ++pos_;
        const std::uint32_t condition = parseOr();
        expectName("else");
        const std::uint32_t otherwise = parseTest();
        return add(Node{NodeKind::IfElse, 0, condition, value, otherwise}, {condition, value, otherwise});
    }

    std::uint32_t parseBoolChain(const char* keyword, NodeKind kind, std::uint32_t (Parser::*operand)()) {
        const std::uint32_t first = (this->*operand)();
        if (!isName(keyword))
            return first;
        std::vector<std::uint32_t> operands{first};
        while (isName(keyword)) {
            ++pos_;
            operands.push_back((this->*operand)());
        }
        return addWithChildren(Node{kind}, operands, operands);
    }

    std::uint32_t parseOr() { return parseBoolChain("or", NodeKind::Or, &Parser::parseAnd); }
    std::uint32_t parseAnd() { return parseBoolChain("and", NodeKind::And, &Parser::parseNot); }

    std::uint32_t parseNot() {
        if (!isName("not"))
            return parseComparison();
        const DepthGuard guard(*this);
        ++pos_;
        const std::uint32_t operand = parseNot();
        return add(Node{NodeKind::Unary, static_cast<std::uint8_t>(UnaryOp::Not), operand}, {operand});
    }

    std::optional<CompareOp> compareOperator() {
        static constexpr std::array<std::pair<std::string_view, CompareOp>, 6> kSymbols = {{
            {"<", CompareOp::Lt},
            {"<=", CompareOp::Le},
            {">", CompareOp::Gt},
            {">=", CompareOp::Ge},
            {"==", CompareOp::Eq},
            {"!=", CompareOp::Ne},
        }};
        for (const auto& [symbol, op] : kSymbols) {
            if (isOp(symbol)) {
                ++pos_;
                return op;
            }
        }
        if (isName("in")) {
            ++pos_;
            return CompareOp::In;
        }
        if (isName("not") && tokens_[pos_ + 1].kind == TokenKind::Name && tokens_[pos_ + 1].text == "in") {
            pos_ += 2;
            return CompareOp::NotIn;
        }
        if (isName("is"))
            fail(peek(), "the 'is' operator is not supported (use ==)");
        return std::nullopt;
    }

    std::uint32_t parseComparison() {
        const std::uint32_t left = parseArith();
        std::vector<std::uint32_t> pairs;
        std::vector<std::uint32_t> operands{left};
        while (const auto op = compareOperator()) {
            const std::uint32_t right = parseArith();
            pairs.push_back(static_cast<std::uint32_t>(*op));
            pairs.push_back(right);
            operands.push_back(right);
        }
        if (pairs.empty())
            return left;
        return addWithChildren(Node{NodeKind::Compare, 0, left}, pairs, operands);
    }

    std::uint32_t parseBinaryChain(std::initializer_list<std::pair<std::string_view, BinaryOp>> ops,
                                   std::uint32_t (Parser::*operand)()) {
        std::uint32_t left = (this->*operand)();
        while (true) {
            const auto match =
                std::find_if(ops.begin(), ops.end(), [&](const auto& o) { return isOp(o.first); });
            if (match == ops.end())
                return left;
            ++pos_;
            const std::uint32_t right = (this->*operand)();
            left = add(Node{NodeKind::Binary, static_cast<std::uint8_t>(match->second), left, right},
                       {left, right});
        }
    }

    std::uint32_t parseArith() {
        return parseBinaryChain({{"+", BinaryOp::Add}, {"-", BinaryOp::Sub}}, &Parser::parseTerm);
    }

    std::uint32_t parseTerm() {
        return parseBinaryChain(
            {{"*", BinaryOp::Mul}, {"/", BinaryOp::Div}, {"//", BinaryOp::FloorDiv}, {"%", BinaryOp::Mod}},
            &Parser::parseFactor);
    }

    std::uint32_t parseFactor() {
        const DepthGuard guard(*this);
        if (isOp("-") || isOp("+")) {
            const UnaryOp op = isOp("-") ? UnaryOp::Negate : UnaryOp::Plus;
            ++pos_;
            const std::uint32_t operand = parseFactor();
            return add(Node{NodeKind::Unary, static_cast<std::uint8_t>(op), operand}, {operand});
        }
        if (isOp("~"))
            fail(peek(), "bitwise operators are not supported");
        const std::uint32_t base = parsePostfix();
        if (!isOp("**"))
            return base;
        ++pos_;
        const std::uint32_t exponent = parseFactor();
        return add(Node{NodeKind::Binary, static_cast<std::uint8_t>(BinaryOp::Pow), base, exponent},
                   {base, exponent});
    }

    std::uint32_t parsePostfix() {
        std::uint32_t node = parseAtom();
        while (true) {
            if (isOp("(")) {
                node = parseCall(node);
            } else if (isOp("[")) {
                ++pos_;
                const std::uint32_t index = parseTest();
                if (isOp(":"))
                    fail(peek(), "slices are not supported");
                expectOp("]");
                node = add(Node{NodeKind::Subscript, 0, node, index}, {node, index});
            } else if (isOp(".")) {
                fail(peek(), "attribute access is not supported (only math.<member>)");
            } else {
                return node;
            }
        }
    }

    std::uint32_t parseCall(std::uint32_t callee) {
        ++pos_;  // (
        std::vector<std::uint32_t> args;
        while (!isOp(")")) {
            if (peek().kind == TokenKind::Name && tokens_[pos_ + 1].text == "=") {
                fail(peek(), "keyword arguments are not supported");
            }
            if (isOp("*") || isOp("**"))
                fail(peek(), "argument unpacking is not supported");
            if (const auto forAt = comprehensionFor()) {
                if (!args.empty())
                    fail(tokens_[*forAt], "a generator argument must be the only argument");
                args.push_back(parseComprehension(*forAt));
                break;
            }
            args.push_back(parseTest());
            if (!isOp(","))
                break;
            ++pos_;
        }
        expectOp(")");
        return makeCall(callee, args);
    }

    // A comprehension whose element starts here and whose first `for` is at `forAt`: the clauses,
    // then the element with their variables bound.
    std::uint32_t parseComprehension(std::size_t forAt) {
        const std::size_t elementStart = pos_;
        pos_ = forAt;
        const std::size_t outerScopes = scopes_.size();
        std::vector<std::uint32_t> clauses;
        std::vector<std::uint32_t> operands;
        while (isName("for")) {
            ++pos_;
            const Token& target = peek();
            if (target.kind != TokenKind::Name || isKeyword(target.text))
                unexpected();
            ++pos_;
            if (isOp(","))
                fail(peek(), "tuple targets in comprehensions are not supported");
            expectName("in");
            const std::uint32_t iterable = parseOr();
            const std::uint32_t slot = bindLocal(std::string(target.text));
            clauses.insert(clauses.end(), {static_cast<std::uint32_t>(ClauseKind::For), slot, iterable});
            operands.push_back(iterable);
            while (isName("if")) {
                ++pos_;
                const std::uint32_t condition = parseOr();
                clauses.insert(clauses.end(), {static_cast<std::uint32_t>(ClauseKind::If), condition, 0});
                operands.push_back(condition);
            }
        }
        const std::size_t end = pos_;
        pos_ = elementStart;
        const std::uint32_t element = parseTest();
        if (pos_ != forAt)
            unexpected();
        pos_ = end;
        scopes_.resize(outerScopes);
        operands.push_back(element);
        return addWithChildren(Node{NodeKind::Comprehension, 0, element}, clauses, operands);
    }

    std::uint32_t parseTupleTail(std::uint32_t first, std::string_view closer) {
        std::vector<std::uint32_t> items{first};
        while (isOp(",")) {
            ++pos_;
            if (closer.empty() ? (peek().kind == TokenKind::End || peek().kind == TokenKind::Newline)
                               : isOp(closer)) {
                break;
            }
            items.push_back(parseTest());
        }
        return addWithChildren(Node{NodeKind::ListDisplay}, items, items);
    }

    // ( ... ) or [ ... ]: a parenthesized expression, a tuple, a list or a comprehension.
    std::uint32_t parseDisplay(std::string_view closer) {
        ++pos_;
        if (isOp(closer)) {
            ++pos_;
            return addWithChildren(Node{NodeKind::ListDisplay}, {}, {});
        }
        if (const auto forAt = comprehensionFor()) {
            const std::uint32_t comprehension = parseComprehension(*forAt);
            expectOp(closer);
            return comprehension;
        }
        std::uint32_t node = parseTest();
        if (isOp(",") || closer == "]")
            node = parseTupleTail(node, closer);
        expectOp(closer);
        return node;
    }

    std::uint32_t parseAtom() {
        const Token& token = peek();
        if (token.kind == TokenKind::Number) {
            ++pos_;
            return addConstant(token.literal);
        }
        if (token.kind == TokenKind::String) {
            std::string text;
            while (peek().kind == TokenKind::String)
                text += tokens_[pos_++].literal.as<std::string>();
            return addConstant(Value(std::move(text)));
        }
        if (token.kind == TokenKind::Operator) {
            if (token.text == "(")
                return parseDisplay(")");
            if (token.text == "[")
                return parseDisplay("]");
            if (token.text == "{")
                fail(token, "dict and set displays are not supported");
            unexpected();
        }
        if (token.kind != TokenKind::Name)
            unexpected();
        return parseName();
    }

    std::uint32_t parseName() {
        const Token& token = peek();
        ++pos_;
        if (token.text == "True")
            return addConstant(Value(true));
        if (token.text == "False")
            return addConstant(Value(false));
        if (token.text == "None")
            return addConstant(Value());
        if (isKeyword(token.text)) {
            --pos_;
            unexpected();
        }
        if (const auto slot = findLocal(token.text))
            return add(Node{NodeKind::Local, 0, *slot}, {});
        if (token.text == "math")
            return parseMathMember(token);
        if (const auto builtin = findBuiltin(token.text))
            return addConstant(Value(FunctionRef{*builtin}));
        return add(Node{NodeKind::Setting, 0, internName(token.text)}, {});
    }

    std::uint32_t parseMathMember(const Token& math) {
        if (!isOp("."))
            fail(math, "'math' can only be used as math.<member>");
        ++pos_;
        const Token& member = peek();
        if (member.kind != TokenKind::Name)
            unexpected();
        ++pos_;
        const auto value = findMathMember(member.text);
        if (!value)
            fail(member, "unknown function or constant 'math." + std::string(member.text) + "'");
        return addConstant(*value);
    }
};

}  // namespace

Expression parse(std::string_view source) {
    return Parser(source, tokenize(source)).run();
}

}  // namespace mixengine::formula
