// libFuzzer target: the setting formula parser and evaluator (settings/formula/Formula.h) with an
// environment that knows a few settings of each type and Cura's functions. The whole input is the
// formula text.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "settings/formula/Formula.h"

namespace {

using mixengine::formula::List;
using mixengine::formula::Value;

class FuzzEnvironment : public mixengine::formula::Environment {
  public:
    std::optional<Value> lookup(std::string_view name) const override {
        if (name == "layer_height")
            return Value(0.1);
        if (name == "wall_line_count")
            return Value(std::int64_t{3});
        if (name == "support_enable")
            return Value(true);
        if (name == "infill_pattern")
            return Value(std::string("grid"));
        if (name == "machine_disallowed_areas")
            return Value(List{Value(List{Value(std::int64_t{1}), Value(2.5)})});
        return std::nullopt;
    }

    std::optional<Value> callFunction(std::string_view name, const std::vector<Value>& args) const override {
        if (name == "extruderValues" || name == "extruderValue" || name == "resolveOrValue" ||
            name == "valueFromContainer" || name == "extruderValueFromContainer") {
            const Value* key = args.empty() ? nullptr : &args.back();
            const std::optional<Value> found =
                key != nullptr && key->is<std::string>() ? lookup(key->as<std::string>()) : std::nullopt;
            const Value result = found ? *found : Value();
            return name == "extruderValues" ? Value(List{result, result}) : result;
        }
        if (name == "defaultExtruderPosition")
            return Value(std::string("0"));
        return std::nullopt;
    }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view source(reinterpret_cast<const char*>(data), size);
    try {
        const mixengine::formula::Expression expression = mixengine::formula::parse(source);
        (void)mixengine::formula::referencedNames(expression);
        const Value value = mixengine::formula::evaluate(expression, FuzzEnvironment());
        (void)mixengine::formula::toPythonStr(value);
        (void)mixengine::formula::toPythonRepr(value);
    } catch (const mixengine::formula::FormulaError&) {
    }
    return 0;
}
