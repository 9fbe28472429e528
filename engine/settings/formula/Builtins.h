#pragma once
// Python built-in functions and the `math` module for formulas, internal to the formula code.
//
// Built-ins: abs all any bool float int len list map max min round sorted str sum.
// math:      sqrt ceil floor trunc log (1 or 2 args) log10 log2 exp sin cos tan asin acos atan atan2
//            radians degrees fabs pow isclose hypot, and the constants pi e tau inf nan.
// Calls follow Python 3: round() rounds half to even and returns an int without ndigits,
// math.ceil/floor/trunc return ints, int() truncates, min/max take one iterable or several
// arguments, map() applies a built-in to one or more lists. Errors throw detail::EvalProblem.
#include <optional>
#include <string_view>
#include <vector>

#include "settings/formula/Budget.h"
#include "settings/formula/Value.h"

namespace mixengine::formula {

/// The Python built-in called `name` ("max", "round", ...), if it is one.
std::optional<Builtin> findBuiltin(std::string_view name);

/// The member `math.<name>`: a FunctionRef for functions, a float for constants.
std::optional<Value> findMathMember(std::string_view name);

/// Calls a built-in. Checks the argument count and types. `budget` counts the steps of the ones
/// that walk a list or str (sum, min, max, any, all, map, sorted) and the elements they create.
Value callBuiltin(Builtin id, const std::vector<Value>& args, detail::Budget& budget);

/// Calls a math.* built-in; precondition: id is one of the Math* ids and the argument count was checked.
Value callMathBuiltin(Builtin id, const std::vector<Value>& args);

}  // namespace mixengine::formula
