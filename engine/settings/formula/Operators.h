#pragma once
// Python's operators on formula Values, internal to the formula code. Type errors, division by
// zero and int64 overflow throw detail::EvalProblem with Python's wording.
//
//   + - * / // % **   numbers with bool -> int -> float promotion; `/` always gives a float; `//` and
//                     `%` are floored (the remainder takes the divisor's sign); str and list `+`
//                     concatenate, `*` with an int repeats (sizes counted by the evaluation's Budget)
//   < <= > >=         numbers across types (exact int/float comparison), str by code point,
//                     lists lexicographically; anything else is a type error
//   == !=             pythonEquals(); never an error
//   in, not in        substring for str (linear time), element (by ==) for list
//   x[i]              lists and strs, negative i counts from the end
#include <compare>
#include <string>
#include <vector>

#include "settings/formula/Budget.h"
#include "settings/formula/Expression.h"
#include "settings/formula/Value.h"

namespace mixengine::formula {

Value unaryOp(detail::UnaryOp op, const Value& operand);
/// `budget` counts the elements of a concatenation or repetition before they are allocated.
Value binaryOp(detail::BinaryOp op, const Value& left, const Value& right, detail::Budget& budget);
bool compareOp(detail::CompareOp op, const Value& left, const Value& right);

/// Python's ordering for <, <=, >, >=, min(), max() and sorted(); `symbol` names the operator
/// in the error for values that cannot be ordered.
std::partial_ordering pythonOrder(const Value& left, const Value& right, const char* symbol);

Value subscript(const Value& container, const Value& index);

/// The elements Python iterates over: a list's items or a str's characters (as 1-char strs), a
/// copy counted by `budget`.
List iterate(const Value& iterable, std::string_view context, detail::Budget& budget);

/// The number of characters (UTF-8 code point sequences) of a str: Python's len().
std::size_t characterCount(std::string_view text);

}  // namespace mixengine::formula
