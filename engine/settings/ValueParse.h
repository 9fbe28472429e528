#pragma once
// Parsing of setting values from their text form (as Cura sends them, Python str() of the value).
// Every function throws InputError naming the key and the value when the text does not parse.
//
// Units follow Cura's definitions: lengths are millimetres in text and microns (int64) once
// parsed; ratios are percentages in text and fractions once parsed; angles are degrees in text.
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/Point.h"

namespace mixengine {

bool parseBool(std::string_view key, std::string_view text);               ///< True/False/true/yes/on/1/0/...
double parseReal(std::string_view key, std::string_view text);             ///< finite doubles only
long long parseInteger(std::string_view key, std::string_view text);       ///< "3", also "3.0"
coord_um parseLengthMicrons(std::string_view key, std::string_view text);  ///< mm → µm, rounded
double parseRatio(std::string_view key, std::string_view text);            ///< percent → fraction
std::vector<double> parseRealList(std::string_view key, std::string_view text);  ///< "[1, 2.5]"
/// "[[-20, 10], [10, 10], ...]" (one polygon, mm) → microns.
Path parsePolygonMicrons(std::string_view key, std::string_view text);
/// "[[[x, y], ...], [[x, y], ...]]" (several polygons, mm) → microns.
Paths parsePolygonsMicrons(std::string_view key, std::string_view text);
/// "[[a,b,c],[d,e,f],[g,h,i]]" → row-major 3x3.
std::array<std::array<double, 3>, 3> parseMatrix3(std::string_view key, std::string_view text);

/// A nested list of numbers in Python / JSON form; leaves are numbers.
struct NumberTree {
    bool is_leaf = false;
    double number = 0;
    std::vector<NumberTree> children;
};
NumberTree parseNumberTree(std::string_view key, std::string_view text);

}  // namespace mixengine
