#pragma once
// The token cursor, node pool and scopes behind the formula parser (Parser.cpp), internal to the
// formula code. Guards the nesting depth so that hostile input cannot overflow the stack, either
// while parsing or later while evaluating the tree.
#include <algorithm>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "settings/formula/Expression.h"
#include "settings/formula/FormulaError.h"
#include "settings/formula/Lexer.h"

namespace mixengine::formula {

class ParserState {
  public:
    ParserState(std::string_view source, std::vector<Token> tokens)
        : tokens_(std::move(tokens)), closers_(matchBrackets(tokens_)) {
        data_.source = std::string(source);
    }

  protected:
    static constexpr int kMaxRecursion = 200;             // nested brackets / unary operators
    static constexpr std::uint32_t kMaxTreeDepth = 1000;  // e.g. a + a + ... + a

    // Counts the recursion depth of the parsing functions that can nest.
    class DepthGuard {
      public:
        explicit DepthGuard(ParserState& p) : p_(p) {
            if (++p_.recursion_ > kMaxRecursion)
                p_.fail(p_.peek(), "expression nested too deeply");
        }
        ~DepthGuard() { --p_.recursion_; }
        DepthGuard(const DepthGuard&) = delete;
        DepthGuard& operator=(const DepthGuard&) = delete;

      private:
        ParserState& p_;
    };

    const Token& peek() const { return tokens_[pos_]; }
    bool isOp(std::string_view op) const { return peek().kind == TokenKind::Operator && peek().text == op; }
    bool isName(std::string_view word) const { return peek().kind == TokenKind::Name && peek().text == word; }

    [[noreturn]] void fail(const Token& at, const std::string& problem) const {
        throw FormulaError(data_.source,
                           "invalid syntax at " + describePosition(data_.source, at.offset) + ": " + problem);
    }

    [[noreturn]] void unexpected() const {
        const Token& t = peek();
        if (t.kind == TokenKind::End)
            fail(t, "unexpected end of formula");
        if (t.kind == TokenKind::Newline)
            fail(t, "unexpected line break");
        fail(t, "unexpected '" + std::string(t.text) + "'");
    }

    void expectOp(std::string_view op) {
        if (!isOp(op))
            unexpected();
        ++pos_;
    }

    void expectName(std::string_view word) {
        if (!isName(word))
            unexpected();
        ++pos_;
    }

    /// Appends a node; `operands` are its child nodes, used to bound the tree depth.
    std::uint32_t add(detail::Node node, std::initializer_list<std::uint32_t> operands) {
        return addNode(node, depthOver(operands.begin(), operands.end()));
    }

    /// Appends a node whose `children` range holds `stored`; `operands` are its child nodes.
    std::uint32_t addWithChildren(detail::Node node, const std::vector<std::uint32_t>& stored,
                                  const std::vector<std::uint32_t>& operands) {
        node.first = static_cast<std::uint32_t>(data_.children.size());
        node.count = static_cast<std::uint32_t>(stored.size());
        data_.children.insert(data_.children.end(), stored.begin(), stored.end());
        return addNode(node, depthOver(operands.begin(), operands.end()));
    }

    std::uint32_t addConstant(Value v) {
        data_.constants.push_back(std::move(v));
        return add(detail::Node{detail::NodeKind::Constant, 0,
                                static_cast<std::uint32_t>(data_.constants.size() - 1)},
                   {});
    }

    std::uint32_t internName(std::string_view name) {
        for (std::size_t i = 0; i < data_.names.size(); ++i) {
            if (data_.names[i] == name)
                return static_cast<std::uint32_t>(i);
        }
        data_.names.emplace_back(name);
        return static_cast<std::uint32_t>(data_.names.size() - 1);
    }

    /// A call: of a built-in or an Environment function (then the callee node, a constant or a
    /// setting name, becomes the call), or of a computed value.
    std::uint32_t makeCall(std::uint32_t callee, const std::vector<std::uint32_t>& args) {
        const detail::Node target = data_.nodes[callee];
        const bool builtin =
            target.kind == detail::NodeKind::Constant && data_.constants[target.a].is<FunctionRef>();
        if (!builtin && target.kind != detail::NodeKind::Setting) {
            return addWithChildren(detail::Node{detail::NodeKind::CallValue, 0, callee}, args,
                                   withCallee(callee, args));
        }
        detail::Node call{builtin ? detail::NodeKind::CallBuiltin : detail::NodeKind::CallExternal};
        if (builtin) {
            call.op = static_cast<std::uint8_t>(data_.constants[target.a].as<FunctionRef>().id);
        } else {
            call.a = target.a;
        }
        call.first = static_cast<std::uint32_t>(data_.children.size());
        call.count = static_cast<std::uint32_t>(args.size());
        data_.children.insert(data_.children.end(), args.begin(), args.end());
        const std::uint32_t depth = depthOver(args.begin(), args.end());
        if (depth > kMaxTreeDepth)
            fail(peek(), "expression nested too deeply");
        data_.nodes[callee] = call;
        depths_[callee] = depth;
        return callee;
    }

    /// Where the element starting here is followed by a comprehension's first `for` (as in
    /// `[p for p in xs]` or `all(p for p in xs)`): the first `for` at this bracket level before
    /// its `,` or closing bracket. Looks at the tokens of this level only (it jumps over brackets),
    /// nothing is parsed.
    std::optional<std::size_t> comprehensionFor() const {
        for (std::size_t i = pos_; tokens_[i].kind != TokenKind::End; ++i) {
            const Token& t = tokens_[i];
            if (t.kind == TokenKind::Name && t.text == "for")
                return i;
            if (isOpening(t)) {
                i = closers_[i];  // then past it
                if (tokens_[i].kind == TokenKind::End)
                    return std::nullopt;
            } else if (isClosing(t) || (t.kind == TokenKind::Operator && t.text == ",")) {
                return std::nullopt;
            }
        }
        return std::nullopt;
    }

    std::uint32_t bindLocal(std::string name) {
        const std::uint32_t slot = data_.localCount++;
        scopes_.emplace_back(std::move(name), slot);
        return slot;
    }

    std::optional<std::uint32_t> findLocal(std::string_view name) const {
        for (auto it = scopes_.rbegin(); it != scopes_.rend(); ++it) {
            if (it->first == name)
                return it->second;
        }
        return std::nullopt;
    }

    Expression finish(std::uint32_t root) {
        data_.root = root;
        return Expression(std::move(data_));
    }

    std::vector<Token> tokens_;
    std::vector<std::size_t> closers_;  // matchBrackets(tokens_)
    std::size_t pos_ = 0;
    std::vector<std::pair<std::string, std::uint32_t>> scopes_;  // comprehension variables, innermost last

  private:
    template <typename It>
    std::uint32_t depthOver(It begin, It end) const {
        std::uint32_t depth = 0;
        for (It it = begin; it != end; ++it)
            depth = std::max(depth, depths_[*it]);
        return depth + 1;
    }

    std::uint32_t addNode(const detail::Node& node, std::uint32_t depth) {
        if (depth > kMaxTreeDepth)
            fail(peek(), "expression nested too deeply");
        data_.nodes.push_back(node);
        depths_.push_back(depth);
        return static_cast<std::uint32_t>(data_.nodes.size() - 1);
    }

    static bool isOpening(const Token& t) {
        return t.kind == TokenKind::Operator && (t.text == "(" || t.text == "[" || t.text == "{");
    }
    static bool isClosing(const Token& t) {
        return t.kind == TokenKind::Operator && (t.text == ")" || t.text == "]" || t.text == "}");
    }

    /// For each opening bracket, the index of the closing bracket that ends it, or of the End token
    /// when it is not closed (brackets of another kind are the parser's error to report).
    static std::vector<std::size_t> matchBrackets(const std::vector<Token>& tokens) {
        std::vector<std::size_t> closers(tokens.size(), tokens.size() - 1);
        std::vector<std::size_t> open;
        for (std::size_t i = 0; i < tokens.size(); ++i) {
            if (isOpening(tokens[i])) {
                open.push_back(i);
            } else if (isClosing(tokens[i]) && !open.empty()) {
                closers[open.back()] = i;
                open.pop_back();
            }
        }
        return closers;
    }

    static std::vector<std::uint32_t> withCallee(std::uint32_t callee,
                                                 const std::vector<std::uint32_t>& args) {
        std::vector<std::uint32_t> all(args);
        all.push_back(callee);
        return all;
    }

    detail::ExpressionData data_;
    std::vector<std::uint32_t> depths_;  // tree depth below each node
    int recursion_ = 0;
};

}  // namespace mixengine::formula
