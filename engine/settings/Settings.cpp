#include "settings/Settings.h"

#include "common/Error.h"
#include "geometry/Angles.h"
#include "settings/ValueParse.h"

namespace mixengine {

const std::string& Settings::text(std::string_view key) const {
    auto it = values_.find(key);
    if (it == values_.end()) {
        throw InputError("setting '" + std::string(key) + "' has no value in " + scope_ +
                         " (not in the definitions, not given with -s)");
    }
    return it->second;
}

bool Settings::boolean(std::string_view key) const {
    return parseBool(key, text(key));
}
double Settings::real(std::string_view key) const {
    return parseReal(key, text(key));
}
long long Settings::integer(std::string_view key) const {
    return parseInteger(key, text(key));
}
coord_um Settings::lengthMicrons(std::string_view key) const {
    return parseLengthMicrons(key, text(key));
}
double Settings::millimetres(std::string_view key) const {
    return real(key);
}
double Settings::ratio(std::string_view key) const {
    return parseRatio(key, text(key));
}
double Settings::angleRadians(std::string_view key) const {
    return radiansFromDegrees(real(key));
}
int Settings::extruderIndex(std::string_view key) const {
    return static_cast<int>(integer(key));
}
Path Settings::polygonMicrons(std::string_view key) const {
    return parsePolygonMicrons(key, text(key));
}
Paths Settings::polygonsMicrons(std::string_view key) const {
    return parsePolygonsMicrons(key, text(key));
}
std::vector<double> Settings::realList(std::string_view key) const {
    return parseRealList(key, text(key));
}

Matrix3 Settings::matrix3(std::string_view key) const {
    auto rows = parseMatrix3(key, text(key));
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
