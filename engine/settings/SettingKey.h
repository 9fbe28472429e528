#pragma once
// A setting's key as the engine reads it: its name and the unit its text is read in. Every key the
// engine reads is declared once, in settings/SettingKeys.inc (settings/SettingKeys.h makes each a
// constant in namespace mixengine::key), and Settings' getters take only these keys, each getter only
// the units it can read: a misspelt or undeclared key does not compile, and a length cannot be read
// as a speed. The test SettingKeys.EveryDeclaredKeyIsDefined holds the declarations against Cura's
// definitions and ours (settings/mixengine/): every key defined, with a type and unit that agree.
#include <string_view>

namespace mixengine {

/// The unit a setting's text is read in (the definitions' `type` and `unit`).
enum class SettingUnit {
    Bool,         ///< bool
    Integer,      ///< int without a unit
    Real,         ///< float or int in a unit with no getter of its own (mm³, mm², °C/s, ...)
    Millimetres,  ///< float, mm (or a machine or mesh position, which the definitions leave unitless)
    Percent,      ///< float, % (ratio() gives the fraction, percent() the number)
    Degrees,      ///< float or int, °
    MmPerS,       ///< float, mm/s (speeds and jerks)
    MmPerS2,      ///< float, mm/s²
    Celsius,      ///< float, °C
    Seconds,      ///< float, s
    Text,         ///< enum or str
    Extruder,     ///< extruder or optional_extruder: an extruder train's number, -1 for "not set"
    Polygon,      ///< polygon: [[x, y], ...] in mm
    Polygons,     ///< polygons: [[[x, y], ...], ...] in mm
    RealList,     ///< [int]: a list of numbers ("[0, 90]")
    Matrix,       ///< a 3×3 matrix as Cura writes mesh_rotation_matrix
};

/// A declared key. Only settings/SettingKeys.h makes them; pass them by value.
template <SettingUnit U>
struct Key {
    std::string_view name;
};

/// A declaration as the registry lists it (settings/SettingKeys.h, declaredSettingKeys()).
struct DeclaredKey {
    std::string_view name;
    SettingUnit unit;
    bool from_frontend = false;  ///< added by Cura's frontend (settings/FrontendValues.h), not a definition
};

std::string_view unitName(SettingUnit unit);

}  // namespace mixengine
