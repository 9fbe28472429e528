#pragma once
// Settings for unit tests as a slice sees them: every key with the value the definitions give it
// (Cura's fdmprinter and fdmextruder with their formulas evaluated, plus settings/mixengine/), and the
// test's own values on top. The engine reads no key without a definition (settings/SettingKeys.h), so
// a hand-made scope of a few keys is not what any stage receives.
#include <string>
#include <utility>

#include "settings/DefinitionSet.h"
#include "settings/Resolver.h"

namespace mixengine::test {

/// Extruder 0's resolved values (the global ones and the train's own) with `values` on top.
inline Settings defaultsWith(std::string scope, const SettingValues& values = {}) {
    static const ResolvedMachine machine =
        resolveMachine(loadDefinitionSet("fdmprinter", defaultSearchPath(nullptr)), {});
    SettingValues all = machine.extruders.front().all();
    for (const auto& [key, value] : values)
        all[key] = value;
    return Settings(std::move(scope), std::move(all));
}

}  // namespace mixengine::test
