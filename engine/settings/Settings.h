#pragma once
// A resolved, immutable view of the settings of one scope (global, one extruder train, one mesh):
// every key with its final text value, and typed getters that carry the unit in their name.
//
// The getters take only keys declared in settings/SettingKeys.inc, each getter only the units it
// reads (settings/SettingKey.h). A missing key is an InputError naming the key and the scope, never a
// silent default; a malformed value is an InputError naming the key and the value (see
// settings/ValueParse.h). Unknown keys given by the user are kept (all()) and passed on.
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/Matrix3.h"
#include "geometry/Point.h"
#include "settings/SettingKeys.h"

namespace mixengine {

using SettingValues = std::map<std::string, std::string, std::less<>>;

class Settings {
  public:
    Settings() = default;
    Settings(std::string scope, SettingValues values)
        : scope_(std::move(scope)), values_(std::move(values)) {}

    const std::string& scope() const { return scope_; }
    const SettingValues& all() const { return values_; }

    /// Whether the scope holds the key. Every resolved scope holds every defined key; only a scope
    /// built by hand (a test, a message's partial values) may lack one.
    template <SettingUnit U>
    bool has(Key<U> key) const {
        return values_.find(key.name) != values_.end();
    }
    /// The text of a key named at run time, or null: only for code that handles keys it cannot know in
    /// advance (a user's {key} tokens in start G-code, overlays of one scope on another).
    const std::string* find(std::string_view name) const {
        auto it = values_.find(name);
        return it == values_.end() ? nullptr : &it->second;
    }
    /// The raw text of any key.
    template <SettingUnit U>
    const std::string& text(Key<U> key) const {
        return textOf(key.name);
    }

    bool boolean(Key<SettingUnit::Bool> key) const;
    long long integer(Key<SettingUnit::Integer> key) const;
    double real(Key<SettingUnit::Real> key) const;
    coord_um lengthMicrons(Key<SettingUnit::Millimetres> key) const;  ///< mm in text
    double millimetres(Key<SettingUnit::Millimetres> key) const;
    double velocityMmPerS(Key<SettingUnit::MmPerS> key) const { return number(key.name); }
    double accelerationMmPerS2(Key<SettingUnit::MmPerS2> key) const { return number(key.name); }
    double temperatureCelsius(Key<SettingUnit::Celsius> key) const { return number(key.name); }
    double durationSeconds(Key<SettingUnit::Seconds> key) const { return number(key.name); }
    double ratio(Key<SettingUnit::Percent> key) const;  ///< percent in text → fraction (50 → 0.5)
    double percent(Key<SettingUnit::Percent> key) const { return number(key.name); }
    double angleDegrees(Key<SettingUnit::Degrees> key) const { return number(key.name); }
    double angleRadians(Key<SettingUnit::Degrees> key) const;
    int extruderIndex(Key<SettingUnit::Extruder> key) const;  ///< -1 = "not set" for optional extruders
    Path polygonMicrons(Key<SettingUnit::Polygon> key) const;
    Paths polygonsMicrons(Key<SettingUnit::Polygons> key) const;
    std::vector<double> realList(Key<SettingUnit::RealList> key) const;
    Matrix3 matrix3(Key<SettingUnit::Matrix> key) const;
    /// Any single number, in its key's own unit (for code that handles speeds, accelerations and
    /// jerks alike, e.g. the first layers' slow-down).
    template <SettingUnit U>
    requires(U != SettingUnit::Bool && U != SettingUnit::Text && U != SettingUnit::Polygon &&
             U != SettingUnit::Polygons && U != SettingUnit::RealList &&
             U != SettingUnit::Matrix) double number(Key<U> key) const {
        return number(key.name);
    }

    /// Returns a copy with `overlay` applied on top (used for mesh groups and meshes).
    Settings with(std::string scope, const SettingValues& overlay) const;

  private:
    const std::string& textOf(std::string_view name) const;
    double number(std::string_view name) const;

    std::string scope_;
    SettingValues values_;
};

}  // namespace mixengine
