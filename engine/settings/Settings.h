#pragma once
// A resolved, immutable view of the settings of one scope (global, one extruder train, one mesh):
// every key with its final text value, and typed getters that carry the unit in their name.
//
// Missing keys are an InputError naming the key and the scope; malformed values are an
// InputError naming the key and the value (see settings/ValueParse.h). Unknown keys given by the
// user are kept and returned like any other.
#include <map>
#include <string>
#include <string_view>

#include "geometry/Matrix3.h"
#include "geometry/Point.h"

namespace mixengine {

using SettingValues = std::map<std::string, std::string, std::less<>>;

class Settings {
  public:
    Settings() = default;
    Settings(std::string scope, SettingValues values)
        : scope_(std::move(scope)), values_(std::move(values)) {}

    const std::string& scope() const { return scope_; }
    bool has(std::string_view key) const { return values_.find(key) != values_.end(); }
    const std::string& text(std::string_view key) const;
    const SettingValues& all() const { return values_; }

    bool boolean(std::string_view key) const;
    /// A switch that may be absent: boolean(key) when present, false when not.
    bool flag(std::string_view key) const { return has(key) && boolean(key); }
    double real(std::string_view key) const;
    long long integer(std::string_view key) const;
    coord_um lengthMicrons(std::string_view key) const;  ///< mm in text
    double millimetres(std::string_view key) const;
    double velocityMmPerS(std::string_view key) const { return real(key); }
    double accelerationMmPerS2(std::string_view key) const { return real(key); }
    double temperatureCelsius(std::string_view key) const { return real(key); }
    double durationSeconds(std::string_view key) const { return real(key); }
    double ratio(std::string_view key) const;  ///< percent in text → fraction (50 → 0.5)
    double angleDegrees(std::string_view key) const { return real(key); }
    double angleRadians(std::string_view key) const;
    int extruderIndex(std::string_view key) const;  ///< -1 = "not set" for optional extruders
    Path polygonMicrons(std::string_view key) const;
    Paths polygonsMicrons(std::string_view key) const;
    std::vector<double> realList(std::string_view key) const;
    Matrix3 matrix3(std::string_view key) const;

    /// Returns a copy with `overlay` applied on top (used for mesh groups and meshes).
    Settings with(std::string scope, const SettingValues& overlay) const;

  private:
    std::string scope_;
    SettingValues values_;
};

}  // namespace mixengine
