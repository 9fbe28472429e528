#pragma once
// Setting formulas: the Python expressions in Cura definitions (`value`, `resolve`, `enabled`,
// `minimum_value`, `maximum_value`, `*_warning`), parsed once and evaluated with Python semantics.
//
//   Expression e = parse("max(0.1, layer_height * 2) if support_enable else 0");
//   Value v = evaluate(e, environment);          // Python's result, e.g. 0.4 (a float)
//   referencedNames(e);                          // {"layer_height", "support_enable"}
//   toPythonStr(v);                              // "0.4": what Cura would send for it
//
// Supported syntax: literals (int, float, str with ' " ''' """ and escapes, True False None),
// lists and tuples, + - * / // % ** and unary - + not, chained comparisons < <= > >= == != in
// `not in`, `and`/`or` (returning an operand), `x if c else y`, calls, subscripts with negative
// indices, `math.<member>`, and generator/list comprehensions (`all(p != 'x' for p in xs)`).
// Lambdas, slices, dicts, sets, attribute access other than math.*, keyword arguments, `is`
// and bitwise operators are rejected at parse time with a FormulaError.
//
// Name resolution: a comprehension variable, else a Python built-in (Builtins.h) or `math`,
// else a setting key asked of the Environment. A call `f(...)` of a name that is not a built-in
// goes to Environment::callFunction (Cura's extruderValue, extruderValues, resolveOrValue,
// defaultExtruderPosition, valueFromContainer, extruderValueFromContainer).
//
// Bounds: parsing takes time and memory linear in the formula's length (nesting at most 200 deep).
// One evaluation may take at most 1,000,000 steps and create at most 1,000,000 elements (list items
// and string characters, copies included; Budget.h), checked before allocating: beyond, it throws
// FormulaError "too much work (...)" / "too large (...)". Cura's definitions need at most 181 steps
// and 1,200 elements.
//
// Errors: parse() and evaluate() throw FormulaError (an InputError) whose message names the
// formula text and the problem; nothing else escapes except exceptions the Environment throws.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "settings/formula/Expression.h"
#include "settings/formula/FormulaError.h"
#include "settings/formula/Value.h"

namespace mixengine::formula {

/// What a formula can see besides its literals and the built-ins. Implemented by the settings
/// stack; must be usable from const (evaluation does not modify it).
class Environment {
  public:
    virtual ~Environment() = default;

    /// The value of the setting `name`, or nullopt if there is no such setting (evaluate() then
    /// throws FormulaError "unknown name").
    virtual std::optional<Value> lookup(std::string_view name) const = 0;

    /// Calls the Cura function `name` with evaluated arguments, or returns nullopt if there is no
    /// such function (evaluate() then throws FormulaError "unknown function").
    virtual std::optional<Value> callFunction(std::string_view name,
                                              const std::vector<Value>& args) const = 0;
};

/// Parses a formula. Leading/trailing whitespace and newlines are allowed, so are newlines inside
/// brackets. Throws FormulaError for invalid or unsupported syntax.
Expression parse(std::string_view source);

/// Evaluates a parsed formula. Throws FormulaError for runtime errors (unknown name or function,
/// type error, division by zero, math domain or range error, an int conversion outside int64, ...).
/// Thread-safe: an Expression can be evaluated concurrently; the Environment must allow it too.
Value evaluate(const Expression& expression, const Environment& environment);

/// The setting keys the formula depends on, sorted and unique: every free name that is not a
/// built-in, plus every string literal passed directly to an Environment function, since Cura
/// names settings that way (`resolveOrValue('layer_height')`, `extruderValue(n, 'speed')`).
std::vector<std::string> referencedNames(const Expression& expression);

}  // namespace mixengine::formula
