// Definition values → the text Cura sends its engine (Python str() of the value).
#include "settings/JsonText.h"

#include <gtest/gtest.h>

#include <limits>
#include <nlohmann/json.hpp>

namespace mixengine {
namespace {

using nlohmann::json;

TEST(JsonText, Booleans) {
    EXPECT_EQ(jsonToPythonText(json(true)), "True");
    EXPECT_EQ(jsonToPythonText(json(false)), "False");
}

TEST(JsonText, Integers) {
    EXPECT_EQ(jsonToPythonText(json(3)), "3");
    EXPECT_EQ(jsonToPythonText(json(-2)), "-2");
    EXPECT_EQ(jsonToPythonText(json(0)), "0");
    EXPECT_EQ(jsonToPythonText(json::parse("235")), "235");
    EXPECT_EQ(jsonToPythonText(json::parse("18446744073709551615")), "18446744073709551615");
}

TEST(JsonText, FloatsAsPythonRepr) {
    EXPECT_EQ(jsonToPythonText(json(0.1)), "0.1");
    EXPECT_EQ(jsonToPythonText(json(1.0)), "1.0");
    EXPECT_EQ(jsonToPythonText(json(1e-05)), "1e-05");
    EXPECT_EQ(jsonToPythonText(json(0.0001)), "0.0001");
    EXPECT_EQ(jsonToPythonText(json(1e16)), "1e+16");
    EXPECT_EQ(jsonToPythonText(json(123456789.0)), "123456789.0");
    // As parsed from a definition file ("2.85", "6.0", "0.00001").
    EXPECT_EQ(jsonToPythonText(json::parse("2.85")), "2.85");
    EXPECT_EQ(jsonToPythonText(json::parse("6.0")), "6.0");
    EXPECT_EQ(jsonToPythonText(json::parse("0.00001")), "1e-05");
}

TEST(JsonText, FloatLayoutBoundaries) {
    EXPECT_EQ(pythonFloatText(1e15), "1000000000000000.0");
    EXPECT_EQ(pythonFloatText(9999999999999998.0), "9999999999999998.0");
    EXPECT_EQ(pythonFloatText(1e22), "1e+22");
    EXPECT_EQ(pythonFloatText(1.5e-7), "1.5e-07");
    EXPECT_EQ(pythonFloatText(1.234e-5), "1.234e-05");
    EXPECT_EQ(pythonFloatText(0.00012), "0.00012");
    EXPECT_EQ(pythonFloatText(12.5), "12.5");
    EXPECT_EQ(pythonFloatText(-0.5), "-0.5");
    EXPECT_EQ(pythonFloatText(-0.0), "-0.0");
    EXPECT_EQ(pythonFloatText(0.1 + 0.2), "0.30000000000000004");
    EXPECT_EQ(pythonFloatText(2.99792458e+11), "299792458000.0");
    EXPECT_EQ(pythonFloatText(1.7976931348623157e308), "1.7976931348623157e+308");
    EXPECT_EQ(pythonFloatText(5e-324), "5e-324");
    EXPECT_EQ(pythonFloatText(std::numeric_limits<double>::infinity()), "inf");
    EXPECT_EQ(pythonFloatText(-std::numeric_limits<double>::infinity()), "-inf");
    EXPECT_EQ(pythonFloatText(std::numeric_limits<double>::quiet_NaN()), "nan");
}

TEST(JsonText, StringsVerbatim) {
    EXPECT_EQ(jsonToPythonText(json("grid")), "grid");
    EXPECT_EQ(jsonToPythonText(json("RepRap (Marlin/Sprinter)")), "RepRap (Marlin/Sprinter)");
    EXPECT_EQ(jsonToPythonText(json("G28 ;Home\nG1 Z15.0 F6000")), "G28 ;Home\nG1 Z15.0 F6000");
    EXPECT_EQ(jsonToPythonText(json("")), "");
}

TEST(JsonText, NoneForNull) {
    EXPECT_EQ(jsonToPythonText(json(nullptr)), "None");
}

TEST(JsonText, ListsAsPythonRepr) {
    EXPECT_EQ(jsonToPythonText(json::parse("[[-20, 10], [10, 10]]")), "[[-20, 10], [10, 10]]");
    EXPECT_EQ(jsonToPythonText(json::parse("[[-20,10],[10,10],[10,-10],[-20,-10]]")),
              "[[-20, 10], [10, 10], [10, -10], [-20, -10]]");
    EXPECT_EQ(jsonToPythonText(json::parse("[[0.5, 1.0], [2, 1e-05]]")), "[[0.5, 1.0], [2, 1e-05]]");
    EXPECT_EQ(jsonToPythonText(json::parse("[]")), "[]");
    EXPECT_EQ(jsonToPythonText(json::parse("[0, 90]")), "[0, 90]");
    EXPECT_EQ(jsonToPythonText(json::parse("[true, false]")), "[True, False]");
}

TEST(JsonText, StringListsAreQuoted) {
    EXPECT_EQ(jsonToPythonText(json::parse(R"(["a", "b"])")), "['a', 'b']");
    EXPECT_EQ(jsonToPythonText(json::parse(R"([["a"], []])")), "[['a'], []]");
}

}  // namespace
}  // namespace mixengine
