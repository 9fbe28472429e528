#include "settings/Settings.h"

#include "common/Error.h"
#include "geometry/Angles.h"
#include "settings/ValueParse.h"

namespace mixengine {

const std::string& Settings::textOf(std::string_view key) const {
    auto it = values_.find(key);
    if (it == values_.end()) {
        throw InputError("setting '" + std::string(key) + "' has no value in " + scope_ +
                         " (not in the definitions, not given with -s)");
    }
    return it->second;
}

double Settings::number(std::string_view name) const {
    return parseReal(name, textOf(name));
}
bool Settings::boolean(Key<SettingUnit::Bool> key) const {
    return parseBool(key.name, textOf(key.name));
}
double Settings::real(Key<SettingUnit::Real> key) const {
    return number(key.name);
}
long long Settings::integer(Key<SettingUnit::Integer> key) const {
    return parseInteger(key.name, textOf(key.name));
}
coord_um Settings::lengthMicrons(Key<SettingUnit::Millimetres> key) const {
    return parseLengthMicrons(key.name, textOf(key.name));
}
double Settings::millimetres(Key<SettingUnit::Millimetres> key) const {
    return number(key.name);
}
double Settings::ratio(Key<SettingUnit::Percent> key) const {
    return parseRatio(key.name, textOf(key.name));
}
double Settings::angleRadians(Key<SettingUnit::Degrees> key) const {
    return radiansFromDegrees(number(key.name));
}
int Settings::extruderIndex(Key<SettingUnit::Extruder> key) const {
    return static_cast<int>(parseInteger(key.name, textOf(key.name)));
}
Path Settings::polygonMicrons(Key<SettingUnit::Polygon> key) const {
    return parsePolygonMicrons(key.name, textOf(key.name));
}
Paths Settings::polygonsMicrons(Key<SettingUnit::Polygons> key) const {
    return parsePolygonsMicrons(key.name, textOf(key.name));
}
std::vector<double> Settings::realList(Key<SettingUnit::RealList> key) const {
    return parseRealList(key.name, textOf(key.name));
}

Matrix3 Settings::matrix3(Key<SettingUnit::Matrix> key) const {
    auto rows = parseMatrix3(key.name, textOf(key.name));
    Matrix3 matrix;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            matrix.m[r][c] = rows[r][c];
    return matrix;
}

Settings Settings::with(std::string scope, const SettingValues& overlay) const {
    SettingValues merged = values_;
    for (const auto& [key, value] : overlay)
        merged[key] = value;
    return Settings(std::move(scope), std::move(merged));
}

}  // namespace mixengine
