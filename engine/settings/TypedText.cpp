#include "settings/TypedText.h"

#include <cmath>
#include <optional>

#include "common/Error.h"
#include "settings/ValueParse.h"
#include "settings/formula/Formula.h"

namespace mixengine {
namespace {

/// Formulas with no names, to read Python literals such as lists.
class NoNames : public formula::Environment {
  public:
    std::optional<formula::Value> lookup(std::string_view) const override { return std::nullopt; }
    std::optional<formula::Value> callFunction(std::string_view,
                                               const std::vector<formula::Value>&) const override {
        return std::nullopt;
    }
};

// A list value such as "[[0, 0], [1, 0], [0, 1]]", read as the Python expression Cura writes.
// Expressions (`[[0, 0]] * 3`) are evaluated too, within the formula evaluator's bounds; their
// errors (too large, too much work, ...) name the setting and the problem.
formula::Value literal(std::string_view key, std::string_view text) {
    std::optional<formula::Expression> expression;
    try {
        expression = formula::parse(text);
    } catch (const InputError&) {
        throw InputError("setting '" + std::string(key) + "': value '" + std::string(text) +
                         "' is not a Python literal");
    }
    try {
        return formula::evaluate(*expression, NoNames());
    } catch (const formula::FormulaError& e) {
        throw InputError("setting '" + std::string(key) + "': " + e.what());
    }
}

bool looksLikeNumber(std::string_view text) {
    try {
        parseReal("", text);
        return true;
    } catch (const InputError&) {
        return false;
    }
}

}  // namespace

formula::Value valueFromText(std::string_view key, std::string_view type, std::string_view text) {
    if (type == "float")
        return parseReal(key, text);
    if (type == "int" || type == "extruder" || type == "optional_extruder") {
        const double number = parseReal(key, text);
        return static_cast<std::int64_t>(std::llround(number));
    }
    if (type == "bool")
        return parseBool(key, text);
    if (type == "polygon" || type == "polygons" || type == "[int]")
        return literal(key, text);
    if (type == "str" || type == "enum")
        return std::string(text);
    // Unknown keys: numbers as numbers, Python booleans as booleans, everything else as text.
    if (text == "True" || text == "False")
        return text == "True";
    if (looksLikeNumber(text)) {
        const double number = parseReal(key, text);
        const bool integral = text.find_first_of(".eE") == std::string_view::npos;
        if (integral && std::fabs(number) < 9e15)
            return static_cast<std::int64_t>(number);
        return number;
    }
    return std::string(text);
}

formula::Value curaValueFromText(std::string_view key, std::string_view type, std::string_view text) {
    if (type == "float" || type == "int") {
        if (!looksLikeNumber(text))
            return std::int64_t{0};  // Uranium's conversion gives 0 for what does not parse
        const double number = parseReal(key, text);
        const bool integral = text.find_first_of(".eEinfINFnaN") == std::string_view::npos;
        if (integral && std::fabs(number) < 9e15)
            return static_cast<std::int64_t>(number);
        return number;
    }
    if (type == "bool") {
        if (text == "True" || text == "False")
            return text == "True";
        return std::string(text);  // literal_eval fails; Uranium keeps the text ("true")
    }
    if (type == "extruder" || type == "optional_extruder" || type == "[int]" || type == "str" ||
        type == "enum")
        return std::string(text);
    return valueFromText(key, type, text);
}

std::string textFromValue(const formula::Value& value) {
    return formula::toPythonStr(value);
}

}  // namespace mixengine
