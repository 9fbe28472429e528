#pragma once
// The registry: every setting key the engine reads, declared once in settings/SettingKeys.inc as
// MIXENGINE_SETTING(name, Unit), grouped by the definitions' categories. Each becomes a constant
//   key::layer_height   (a Key<SettingUnit::Millimetres> named "layer_height")
// for Settings' typed getters. Values and defaults come from the definitions only (Cura's
// fdmprinter/fdmextruder and settings/mixengine/*.def.json); the keys Cura's frontend adds before
// slicing (settings/FrontendValues.h) are declared with MIXENGINE_FRONTEND_SETTING.
//
// To read a new setting: declare it in SettingKeys.inc; if it is MixEngine's own, define it (with its
// default) in settings/mixengine/; SettingKeys.EveryDeclaredKeyIsDefined checks both.
#include <span>

#include "settings/SettingKey.h"

namespace mixengine {

namespace key {
#define MIXENGINE_SETTING(name, unit) inline constexpr Key<SettingUnit::unit> name{#name};
#define MIXENGINE_FRONTEND_SETTING(name, unit) MIXENGINE_SETTING(name, unit)
#include "settings/SettingKeys.inc"
#undef MIXENGINE_FRONTEND_SETTING
#undef MIXENGINE_SETTING
}  // namespace key

/// Every declaration of SettingKeys.inc, in its order.
std::span<const DeclaredKey> declaredSettingKeys();

}  // namespace mixengine
