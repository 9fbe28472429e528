#include "settings/NotHonoured.h"

#include <algorithm>
#include <cctype>
#include <nlohmann/json.hpp>
#include <optional>

#include "common/Error.h"
#include "settings/FrontendValues.h"
#include "settings/StackEvaluator.h"
#include "settings/formula/Value.h"

namespace mixengine {
namespace {

constexpr std::string_view kEmbeddedList =
#include "not_honoured_json.inc"
    ;

NotHonouredEntry parseEntry(const std::string& key, const nlohmann::json& entry, const std::string& origin) {
    if (entry.is_string())
        return {key, {}, entry.get<std::string>()};
    const bool values_ok = !entry.contains("values") || entry["values"].is_array();
    if (!entry.is_object() || !values_ok || !entry.contains("why") ||
        (!entry.contains("values") && !entry.contains("multi_extruder_only")))
        throw InputError(origin + ": entry '" + key +
                         "' must be a reason or {\"values\": [...], \"why\": ...}");
    NotHonouredEntry out{key, {}, entry["why"].get<std::string>()};
    if (entry.contains("values")) {
        for (const nlohmann::json& value : entry["values"])
            out.values.push_back(value.is_string() ? value.get<std::string>() : value.dump());
    }
    out.multi_extruder_only = entry.value("multi_extruder_only", false);
    return out;
}

/// The user's values without the listed keys: what the definitions give for those keys.
UserSettings withoutListed(const UserSettings& user, const std::vector<NotHonouredEntry>& list) {
    UserSettings stock = user;
    for (const NotHonouredEntry& entry : list) {
        stock.global.erase(entry.key);
        for (auto& [nr, values] : stock.extruders)
            values.erase(entry.key);
    }
    return stock;
}

bool sameText(std::string_view a, std::string_view b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                      [](char x, char y) { return std::tolower(x) == std::tolower(y); });
}

/// The offending value in one scope as text, or nullopt when this scope honours the entry.
/// The key's value in `scope`, or nullopt where its formula fails (reported as such, with its
/// fallback, by the settings' own formula warning, not here).
std::optional<formula::Value> valueOrNothing(StackEvaluator& stack, int scope, const std::string& key) {
    try {
        return stack.value(scope, key);
    } catch (const InputError&) {
        return std::nullopt;
    }
}

std::optional<std::string> offending(const NotHonouredEntry& entry, StackEvaluator& given,
                                     StackEvaluator& stock, int scope) {
    const std::optional<formula::Value> value = valueOrNothing(given, scope, entry.key);
    if (!value || !given.enabled(scope, entry.key))
        return std::nullopt;  // not there, or hidden in Cura: it acts in neither engine
    const std::optional<formula::Value> reference = valueOrNothing(stock, scope, entry.key);
    if (reference && formula::pythonEquals(*value, *reference))
        return std::nullopt;  // the definitions' own value: nothing the user asked for is ignored
    const std::string text = formula::toPythonStr(*value);
    const bool listed =
        entry.values.empty() || std::any_of(entry.values.begin(), entry.values.end(),
                                            [&](const std::string& v) { return sameText(v, text); });
    return listed ? std::optional<std::string>(text) : std::nullopt;
}

}  // namespace

std::vector<NotHonouredEntry> parseNotHonoured(std::string_view json_text, const std::string& origin) {
    nlohmann::json document;
    try {
        document = nlohmann::json::parse(json_text);
    } catch (const nlohmann::json::exception& e) {
        throw InputError(origin + ": " + e.what());
    }
    if (!document.is_object() || !document.contains("settings") || !document["settings"].is_object())
        throw InputError(origin + ": no \"settings\" object");
    std::vector<NotHonouredEntry> list;
    for (const auto& [key, entry] : document["settings"].items())
        list.push_back(parseEntry(key, entry, origin));
    return list;
}

std::vector<NotHonouredEntry> embeddedNotHonoured() {
    return parseNotHonoured(kEmbeddedList, "not_honoured.json");
}

std::vector<std::string> notHonouredWarnings(const std::vector<NotHonouredEntry>& list,
                                             const DefinitionSet& definitions, const UserSettings& user,
                                             int extruder_count) {
    const UserSettings canonical = withCanonicalKeys(user);
    const UserSettings stock_user = withoutListed(canonical, list);
    StackEvaluator given(definitions, canonical, extruder_count);
    StackEvaluator stock(definitions, stock_user, extruder_count);
    std::vector<std::string> warnings;
    for (const NotHonouredEntry& entry : list) {
        if (entry.multi_extruder_only && extruder_count < 2)
            continue;
        std::optional<std::string> bad = offending(entry, given, stock, StackEvaluator::kGlobal);
        for (int nr = 0; nr < extruder_count && !bad; ++nr)
            bad = offending(entry, given, stock, StackEvaluator::extruderScope(nr));
        if (bad)
            warnings.push_back("setting '" + entry.key + "' has no effect in MixEngine yet (value " + *bad +
                               ": " + entry.why + ")");
    }
    return warnings;
}

}  // namespace mixengine
