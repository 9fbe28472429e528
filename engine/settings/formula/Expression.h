#pragma once
// A parsed formula: an immutable syntax tree stored as a flat node pool. Build one with parse()
// (Formula.h); evaluate it any number of times, from any thread, against any Environment.
//
// The nodes are an implementation detail of the formula code (Parser.cpp builds them,
// Evaluator.cpp walks them); users only need source() and the functions of Formula.h.
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "settings/formula/Value.h"

namespace mixengine::formula {

namespace detail {

enum class NodeKind : std::uint8_t {
    Constant,      // a = index into constants
    Setting,       // a = index into names: a setting key, looked up in the Environment
    Local,         // a = slot of a comprehension variable
    Unary,         // op = UnaryOp, a = operand
    Binary,        // op = BinaryOp, a, b = operands
    And,           // children[first .. first+count): operands, `and` returns the deciding one
    Or,            // same for `or`
    Compare,       // a = leftmost operand; children hold (CompareOp, operand) pairs, count = pairs*2
    IfElse,        // a = condition, b = value if true, c = value if false
    ListDisplay,   // children: the elements of [...] or (..., ...)
    CallBuiltin,   // op = Builtin, children: arguments
    CallExternal,  // a = index into names: a function of the Environment; children: arguments
    CallValue,     // a = node giving the callable; children: arguments
    Subscript,     // a = container, b = index
    Comprehension  // a = element; children hold clauses: (For, slot, iterable) or (If, condition, 0)
};

enum class UnaryOp : std::uint8_t { Negate, Plus, Not };
enum class BinaryOp : std::uint8_t { Add, Sub, Mul, Div, FloorDiv, Mod, Pow };
enum class CompareOp : std::uint8_t { Lt, Le, Gt, Ge, Eq, Ne, In, NotIn };
enum class ClauseKind : std::uint8_t { For, If };

struct Node {
    NodeKind kind = NodeKind::Constant;
    std::uint8_t op = 0;
    std::uint32_t a = 0, b = 0, c = 0;
    std::uint32_t first = 0, count = 0;  // a range of `children`
};

/// The node pool of an Expression.
struct ExpressionData {
    std::string source;
    std::vector<Node> nodes;
    std::vector<std::uint32_t> children;
    std::vector<Value> constants;
    std::vector<std::string> names;  // setting keys and function names
    std::uint32_t root = 0;
    std::uint32_t localCount = 0;  // comprehension variable slots
};

}  // namespace detail

class Expression {
  public:
    explicit Expression(detail::ExpressionData data) : data_(std::move(data)) {}

    /// The formula text this expression was parsed from.
    const std::string& source() const { return data_.source; }

    const detail::ExpressionData& data() const { return data_; }

  private:
    detail::ExpressionData data_;
};

}  // namespace mixengine::formula
