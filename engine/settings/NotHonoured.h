#pragma once
// The Cura settings MixEngine does not act on yet, and the warnings for a slice that uses them.
//
// The list is settings/mixengine/not_honoured.json, embedded at build time (the engine needs no
// files for it). Each entry names a key and either nothing more (any value is not honoured) or the
// values that are not honoured (e.g. adhesion_type raft). A warning is given when a listed value
// differs from the one the definitions give (a machine's own defaults are not the user's request)
// and the setting is enabled (its `enabled` formula: Cura hides it otherwise, and neither engine
// reads it then, e.g. raft_margin without a raft).
// tests/python/test_parity.py keeps the list true: every entry is a strict xfail there.
//
// "The value the definitions give" is the setting's own `value` formula (else its default_value)
// evaluated with every *other* given value in place, without profiles: a key that merely follows a
// parent the user changed is not warned about, a key a profile or the user set is.
#include <string>
#include <string_view>
#include <vector>

#include "settings/DefinitionSet.h"
#include "settings/Resolver.h"

namespace mixengine {

struct NotHonouredEntry {
    std::string key;
    std::vector<std::string> values;  ///< empty: every value but the definitions' is not honoured
    std::string why;
    bool multi_extruder_only =
        false;  ///< "multi_extruder_only": true — only with two or more extruder trains
};

/// Parses the list's JSON text; throws InputError naming `origin` when it is malformed.
std::vector<NotHonouredEntry> parseNotHonoured(std::string_view json_text, const std::string& origin);

/// The list embedded in this build (parsed at each call: a hundred short entries).
std::vector<NotHonouredEntry> embeddedNotHonoured();

/// One line per listed key whose value, in the global scope or any extruder train, is not honoured:
/// "setting 'KEY' has no effect in MixEngine yet (...)". Keys are reported once, in list order; an
/// entry marked multi_extruder_only only when `extruder_count` is 2 or more.
std::vector<std::string> notHonouredWarnings(const std::vector<NotHonouredEntry>& list,
                                             const DefinitionSet& definitions, const UserSettings& user,
                                             int extruder_count);

}  // namespace mixengine
