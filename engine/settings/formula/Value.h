#pragma once
// The value of a setting formula, with Python's types and semantics.
//
//   None      — NoneValue
//   bool      — bool
//   int       — std::int64_t. Python ints are unbounded: int arithmetic (+ - * // ** unary -, abs,
//               sum) whose result does not fit continues as float; int(), round() and
//               math.ceil/floor/trunc of values outside int64 throw FormulaError.
//   float     — double
//   str       — std::string holding UTF-8
//   list      — List (std::vector<Value>); tuples and the results of map() and generator
//               expressions are lists too
//   function  — FunctionRef: a built-in such as `abs` or `math.sqrt` used as a value, e.g. in
//               `map(abs, xs)`
//
// operator== is structural: same type and same payload, so Value(1) != Value(1.0) and
// Value(true) != Value(1). Python's `==` (1 == 1.0 == True) is pythonEquals().
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

namespace mixengine::formula {

struct NoneValue {
    bool operator==(const NoneValue&) const = default;
};

/// Built-in functions a formula can call: Python built-ins and members of `math`.
enum class Builtin : std::uint8_t {
    Abs,
    All,
    Any,
    Bool,
    Float,
    Int,
    Len,
    List,
    Map,
    Max,
    Min,
    Round,
    Sorted,
    Str,
    Sum,
    MathSqrt,
    MathCeil,
    MathFloor,
    MathTrunc,
    MathLog,
    MathLog10,
    MathLog2,
    MathExp,
    MathSin,
    MathCos,
    MathTan,
    MathAsin,
    MathAcos,
    MathAtan,
    MathAtan2,
    MathRadians,
    MathDegrees,
    MathFabs,
    MathPow,
    MathIsclose,
    MathHypot,
};

struct FunctionRef {
    Builtin id;
    bool operator==(const FunctionRef&) const = default;
};

class Value;
using List = std::vector<Value>;

class Value {
  public:
    using Storage = std::variant<NoneValue, bool, std::int64_t, double, std::string, List, FunctionRef>;

    Value() = default;  ///< None
    Value(NoneValue) {}
    Value(bool b) : storage_(b) {}
    /// Any integer type except bool becomes a Python int.
    template <typename I, std::enable_if_t<std::is_integral_v<I> && !std::is_same_v<I, bool>, int> = 0>
    Value(I i) : storage_(static_cast<std::int64_t>(i)) {}
    Value(double d) : storage_(d) {}
    Value(std::string s) : storage_(std::move(s)) {}
    Value(std::string_view s) : storage_(std::string(s)) {}
    Value(const char* s) : storage_(std::string(s)) {}
    Value(List l) : storage_(std::move(l)) {}
    Value(FunctionRef f) : storage_(f) {}

    const Storage& storage() const { return storage_; }

    template <typename T>
    bool is() const {
        return std::holds_alternative<T>(storage_);
    }
    /// The payload; precondition: is<T>().
    template <typename T>
    const T& as() const {
        return std::get<T>(storage_);
    }

    bool isNone() const { return is<NoneValue>(); }
    /// bool, int or float.
    bool isNumber() const { return is<bool>() || is<std::int64_t>() || is<double>(); }

    bool operator==(const Value&) const = default;

  private:
    Storage storage_;
};

/// Python's type name: "NoneType", "bool", "int", "float", "str", "list", "builtin_function_or_method".
std::string_view typeName(const Value& v);

/// Python truthiness: None, False, 0, 0.0, '' and [] are false.
bool truthy(const Value& v);

/// Python `a == b`: numbers compare by value across bool/int/float, lists element-wise.
bool pythonEquals(const Value& a, const Value& b);

/// Python `str(v)`: True/False/None, shortest round-trip floats ('0.1', '1.0', '1e-05', 'inf'),
/// strings unquoted, lists as `[1, 'a', 2.5]` with their elements in repr().
std::string toPythonStr(const Value& v);

/// Python `repr(v)`: like toPythonStr but strings are quoted and escaped ('it\'s' -> "it's").
std::string toPythonRepr(const Value& v);

/// Python `repr(float)`: the shortest string that reads back as the same double.
std::string floatRepr(double d);

/// The Python name of a built-in, e.g. "abs" or "math.sqrt".
std::string_view builtinName(Builtin id);

}  // namespace mixengine::formula
