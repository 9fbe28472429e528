// The registry of setting keys (settings/SettingKeys.inc) held against the definitions: every key the
// engine reads is defined by Cura 4.13's fdmprinter/fdmextruder or by MixEngine's settings/mixengine/,
// with a type and unit its getters can read; the keys Cura's frontend adds are defined by neither and
// are the ones settings/FrontendValues.h adds.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "settings/DefinitionSet.h"
#include "settings/FrontendValues.h"
#include "settings/Resolver.h"
#include "settings/SettingKeys.h"

namespace mixengine {
namespace {

const DefinitionSet& fdmprinter() {
    static const DefinitionSet defs = loadDefinitionSet("fdmprinter", defaultSearchPath(nullptr));
    return defs;
}

/// fdmextruder's settings (extruder_nr, the nozzle offsets, ...): an extruder train's own.
const DefinitionSet& fdmextruder() {
    static const DefinitionSet defs = loadDefinitionSet("fdmextruder", defaultSearchPath(nullptr));
    return defs;
}

const SettingDefinition* definitionOf(std::string_view key) {
    const SettingDefinition* def = fdmprinter().find(key);
    return def != nullptr ? def : fdmextruder().find(key);
}

bool isOneOf(const std::string& text, std::initializer_list<const char*> options) {
    for (const char* option : options)
        if (text == option)
            return true;
    return false;
}

/// Whether a definition of `type` in `unit` reads as `declared`.
bool agrees(SettingUnit declared, const std::string& type, const std::string& unit) {
    const bool real = type == "float";
    switch (declared) {
        case SettingUnit::Bool:
            return type == "bool";
        case SettingUnit::Integer:
            return type == "int";
        case SettingUnit::Real:
            return real || type == "int";
        case SettingUnit::Millimetres:
            return real && (unit == "mm" || unit.empty());
        case SettingUnit::Percent:
            return real && unit == "%";
        case SettingUnit::Degrees:
            return (real || type == "int") && unit == "°";
        case SettingUnit::MmPerS:
            return real && unit == "mm/s";
        case SettingUnit::MmPerS2:
            return real && unit == "mm/s²";
        case SettingUnit::Celsius:
            return real && unit == "°C";
        case SettingUnit::Seconds:
            return real && unit == "s";
        case SettingUnit::Text:
            return isOneOf(type, {"enum", "str"});
        case SettingUnit::Extruder:
            return isOneOf(type, {"extruder", "optional_extruder"});
        case SettingUnit::Polygon:
            return type == "polygon";
        case SettingUnit::Polygons:
            return type == "polygons";
        case SettingUnit::RealList:
            return type == "[int]";
        case SettingUnit::Matrix:
            return type == "str";
    }
    return false;
}

TEST(SettingKeys, EveryDeclaredKeyIsDefined) {
    ASSERT_GT(fdmprinter().settings.size(), 500u);
    int checked = 0;
    for (const DeclaredKey& declared : declaredSettingKeys()) {
        if (declared.from_frontend)
            continue;
        const SettingDefinition* def = definitionOf(declared.name);
        ASSERT_NE(def, nullptr) << declared.name << " is read by the engine but defined nowhere";
        EXPECT_TRUE(agrees(declared.unit, def->type, def->unit))
            << declared.name << " is declared " << unitName(declared.unit) << " but defined as " << def->type
            << " in '" << def->unit << "'";
        ++checked;
    }
    EXPECT_GT(checked, 400);
}

TEST(SettingKeys, DeclaredOnceEach) {
    std::set<std::string_view> seen;
    for (const DeclaredKey& declared : declaredSettingKeys())
        EXPECT_TRUE(seen.insert(declared.name).second) << declared.name << " is declared twice";
}

TEST(SettingKeys, FrontendKeysAreTheOnesTheFrontendAdds) {
    const DefinitionSet& defs = fdmprinter();
    ResolvedMachine machine = resolveMachine(defs, {});
    const SettingValues before = machine.global.all();
    applyFrontendValues(machine, {});
    for (const DeclaredKey& declared : declaredSettingKeys()) {
        if (!declared.from_frontend)
            continue;
        EXPECT_EQ(definitionOf(declared.name), nullptr)
            << declared.name << " is a definition, not the frontend's";
        EXPECT_FALSE(before.contains(std::string(declared.name))) << declared.name;
        EXPECT_NE(machine.global.find(declared.name), nullptr)
            << declared.name << " is not added by the frontend";
    }
}

TEST(SettingKeys, AMissingKeyIsAnErrorNamingIt) {
    const Settings empty("mesh 'cube.stl'", {});
    try {
        (void)empty.boolean(key::support_enable);
        FAIL() << "no error for a missing key";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("'support_enable'"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("mesh 'cube.stl'"), std::string::npos) << e.what();
    }
}

TEST(SettingKeys, GettersReadTheirUnits) {
    const Settings s("global",
                     {{"layer_height", "0.15"}, {"infill_material_flow", "20"}, {"support_angle", "90"}});
    EXPECT_EQ(s.lengthMicrons(key::layer_height), 150);
    EXPECT_DOUBLE_EQ(s.ratio(key::infill_material_flow), 0.2);
    EXPECT_DOUBLE_EQ(s.percent(key::infill_material_flow), 20.0);
    EXPECT_NEAR(s.angleRadians(key::support_angle), 1.5707963267948966, 1e-15);
}

}  // namespace
}  // namespace mixengine
