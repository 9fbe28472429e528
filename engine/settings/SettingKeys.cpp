#include "settings/SettingKeys.h"

#include <array>

namespace mixengine {

namespace {

constexpr std::array kDeclared{
#define MIXENGINE_SETTING(name, unit) DeclaredKey{#name, SettingUnit::unit, false},
#define MIXENGINE_FRONTEND_SETTING(name, unit) DeclaredKey{#name, SettingUnit::unit, true},
#include "settings/SettingKeys.inc"
#undef MIXENGINE_FRONTEND_SETTING
#undef MIXENGINE_SETTING
};

}  // namespace

std::span<const DeclaredKey> declaredSettingKeys() {
    return kDeclared;
}

std::string_view unitName(SettingUnit unit) {
    switch (unit) {
        case SettingUnit::Bool:
            return "bool";
        case SettingUnit::Integer:
            return "integer";
        case SettingUnit::Real:
            return "real";
        case SettingUnit::Millimetres:
            return "mm";
        case SettingUnit::Percent:
            return "%";
        case SettingUnit::Degrees:
            return "°";
        case SettingUnit::MmPerS:
            return "mm/s";
        case SettingUnit::MmPerS2:
            return "mm/s²";
        case SettingUnit::Celsius:
            return "°C";
        case SettingUnit::Seconds:
            return "s";
        case SettingUnit::Text:
            return "text";
        case SettingUnit::Extruder:
            return "extruder";
        case SettingUnit::Polygon:
            return "polygon";
        case SettingUnit::Polygons:
            return "polygons";
        case SettingUnit::RealList:
            return "list";
        case SettingUnit::Matrix:
            return "matrix";
    }
    return "?";
}

}  // namespace mixengine
