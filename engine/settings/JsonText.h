#pragma once
// Conversion of JSON values from definition files to the text form Cura sends to its engine,
// which is Python's str() of the value (True/False, 0.4, [1, 2], strings verbatim).
#include <nlohmann/json_fwd.hpp>
#include <string>

namespace mixengine {

std::string jsonToPythonText(const nlohmann::json& value);

/// Python repr of a float: the shortest text that reads back to the same double, with ".0" for
/// integral values ("1.0", "0.1", "1e-05", "inf").
std::string pythonFloatText(double value);

}  // namespace mixengine
