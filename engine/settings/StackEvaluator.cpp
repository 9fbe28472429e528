#include "settings/StackEvaluator.h"

#include <algorithm>
#include <cmath>

#include "common/Error.h"
#include "settings/TypedText.h"
#include "settings/formula/Formula.h"

namespace mixengine {

struct StackEvaluator::Scope {
    bool is_mesh = false;
    int extruder = -1;  ///< -1 for the global scope
    SettingValues mesh_user;
    std::unordered_map<std::string, formula::Value> memo[3];  ///< by Mode
    std::unordered_set<std::string> busy[3];
};

class StackEvaluator::ScopeEnvironment : public formula::Environment {
  public:
    ScopeEnvironment(StackEvaluator& stack, int scope) : stack_(stack), scope_(scope) {}
    std::optional<formula::Value> lookup(std::string_view name) const override {
        return stack_.value(scope_, name);
    }
    std::optional<formula::Value> callFunction(std::string_view name,
                                               const std::vector<formula::Value>& args) const override {
        return stack_.callCuraFunction(name, args);
    }

  private:
    StackEvaluator& stack_;
    int scope_;
};

namespace {

/// Removes `key` from a busy set when the evaluation of `key` ends, also by an exception.
class BusyGuard {
  public:
    BusyGuard(std::unordered_set<std::string>& set, std::string key) : set_(set), key_(std::move(key)) {
        set_.insert(key_);
    }
    ~BusyGuard() { set_.erase(key_); }
    BusyGuard(const BusyGuard&) = delete;
    BusyGuard& operator=(const BusyGuard&) = delete;

  private:
    std::unordered_set<std::string>& set_;
    std::string key_;
};

std::optional<long long> asInteger(const formula::Value& v) {
    if (v.is<std::int64_t>())
        return v.as<std::int64_t>();
    if (v.is<bool>())
        return v.as<bool>() ? 1 : 0;
    if (v.is<double>() && std::isfinite(v.as<double>()))
        return static_cast<long long>(v.as<double>());
    if (v.is<std::string>()) {
        try {
            return std::stoll(v.as<std::string>());
        } catch (const std::exception&) {
            return std::nullopt;
        }
    }
    return std::nullopt;
}

/// Python's `value == -1` for a number (a string never equals -1).
bool isMinusOne(const formula::Value& v) {
    if (v.is<std::int64_t>())
        return v.as<std::int64_t>() == -1;
    if (v.is<double>())
        return v.as<double>() == -1.0;
    return false;
}

std::string argumentKey(const std::vector<formula::Value>& args, std::size_t index) {
    if (index < args.size() && args[index].is<std::string>())
        return args[index].as<std::string>();
    throw InputError("formula function argument " + std::to_string(index + 1) + " must be a setting name");
}

}  // namespace

StackEvaluator::StackEvaluator(const DefinitionSet& definitions, const UserSettings& user, int extruder_count,
                               const ProfileStack* profiles)
    : definitions_(definitions),
      user_(user),
      profiles_(profiles),
      cura_(profiles != nullptr && profiles->cura),
      extruder_count_(std::max(1, extruder_count)) {
    scopes_.push_back(std::make_unique<Scope>());
    for (int e = 0; e < extruder_count_; ++e) {
        auto scope = std::make_unique<Scope>();
        scope->extruder = e;
        scopes_.push_back(std::move(scope));
    }
}

StackEvaluator::~StackEvaluator() = default;

int StackEvaluator::addMeshScope(SettingValues user, int extruder) {
    auto scope = std::make_unique<Scope>();
    scope->is_mesh = true;
    scope->extruder = extruder;
    scope->mesh_user = std::move(user);
    scopes_.push_back(std::move(scope));
    return static_cast<int>(scopes_.size()) - 1;
}

const SettingDefinition* StackEvaluator::extruderOwn(int extruder, std::string_view key) const {
    // A train without an extruder definition of its own (e.g. -e1 on fdmprinter) uses the first
    // train's definition, as CuraEngine gives every train fdmextruder's settings.
    const ExtruderDefinition* chosen =
        definitions_.extruders.empty() ? nullptr : &definitions_.extruders.front();
    for (const ExtruderDefinition& e : definitions_.extruders) {
        if (e.position == extruder)
            chosen = &e;
    }
    if (!chosen || extruder < 0)
        return nullptr;
    // Borrowed from another train: only the extruder-only keys (machine_nozzle_offset_x, ...), not
    // that train's overrides of machine settings.
    if (chosen->position != extruder && definitions_.find(key))
        return nullptr;
    if (cura_ && chosen->undeclared.count(key))
        return nullptr;  // Cura ignores an override of a key the extruder's chain does not declare
    auto it = chosen->overrides.find(key);
    return it == chosen->overrides.end() ? nullptr : &it->second;
}

const SettingDefinition* StackEvaluator::anyDefinition(std::string_view key) const {
    if (const SettingDefinition* def = definitions_.find(key))
        return def;
    return extruderOwn(0, key);
}

const formula::Expression& StackEvaluator::compiled(const std::string& formula) {
    auto it = expressions_.find(&formula);
    if (it == expressions_.end()) {
        it = expressions_.emplace(&formula, std::make_unique<formula::Expression>(formula::parse(formula)))
                 .first;
    }
    return *it->second;
}

formula::Value StackEvaluator::userValue(std::string_view key, const std::string& text) const {
    const SettingDefinition* def = anyDefinition(key);
    try {
        return typedValue(key, def ? def->type : std::string(), text);
    } catch (const UserValueError&) {
        throw;
    } catch (const InputError& e) {
        throw UserValueError(e.what());
    }
}

formula::Value StackEvaluator::typedValue(std::string_view key, const std::string& type,
                                          std::string_view text) const {
    return cura_ ? curaValueFromText(key, type, text) : valueFromText(key, type, text);
}

formula::Value StackEvaluator::evaluateFormula(int scope, std::string_view key, const std::string& formula) {
    try {
        return formula::evaluate(compiled(formula), ScopeEnvironment(*this, scope));
    } catch (const formula::FormulaError& e) {
        throw InputError("setting '" + std::string(key) + "': formula '" + formula + "': " + e.problem());
    }
}

bool StackEvaluator::enabled(int scope, std::string_view key) {
    const SettingDefinition* def = anyDefinition(key);
    if (!def || !def->enabled_formula)
        return true;
    try {
        return formula::truthy(evaluateFormula(scope, key, *def->enabled_formula));
    } catch (const InputError&) {
        return true;
    }
}

std::optional<formula::Value> StackEvaluator::value(int scope, std::string_view key) {
    if (!anyDefinition(key) && !user_.global.count(std::string(key))) {
        const Scope& s = *scopes_[static_cast<std::size_t>(scope)];
        const bool in_train_user = s.extruder >= 0 && user_.extruders.count(s.extruder) &&
                                   user_.extruders.at(s.extruder).count(std::string(key));
        if (!in_train_user && !s.mesh_user.count(std::string(key)))
            return std::nullopt;
    }
    return resolve(scope, key, Mode::Normal);
}

formula::Value StackEvaluator::resolve(int scope, std::string_view key, Mode mode) {
    Scope& s = *scopes_[static_cast<std::size_t>(scope)];
    // A global key whose `resolve` formula is being evaluated is read without resolving again.
    if (scope == kGlobal && mode == Mode::Normal &&
        s.busy[static_cast<int>(Mode::Normal)].count(std::string(key)))
        mode = Mode::Raw;
    const int m = static_cast<int>(mode);
    const std::string name(key);
    if (auto it = s.memo[m].find(name); it != s.memo[m].end())
        return it->second;
    if (s.busy[m].count(name)) {
        const SettingDefinition* def = anyDefinition(key);
        const std::string formula = def && def->value_formula ? *def->value_formula : std::string("?");
        throw InputError("setting '" + name + "': formula '" + formula + "' depends on itself");
    }
    BusyGuard guard(s.busy[m], name);
    std::optional<formula::Value> result =
        scope == kGlobal ? resolveGlobal(key, mode) : resolveTrain(scope, key, mode);
    if (!result)
        throw InputError("setting '" + name + "' has no value in any definition");
    s.memo[m].emplace(name, *result);
    return *result;
}

std::optional<formula::Value> StackEvaluator::resolveGlobal(std::string_view key, Mode mode) {
    const SettingDefinition* def = definitions_.find(key);
    auto user = user_.global.find(key);
    if (!def) {
        if (user != user_.global.end())
            return userValue(key, user->second);
        if (extruderOwn(0, key))
            return resolve(extruderScope(0), key, Mode::Normal);
        return std::nullopt;
    }
    if (def->resolve_formula && user == user_.global.end() && mode != Mode::Raw) {
        return evaluateFormula(kGlobal, key, *def->resolve_formula);
    }
    if (def->limit_to_extruder && def->settable_per_extruder) {
        if (const std::optional<int> target = limitTarget(kGlobal, *def))
            return resolve(extruderScope(*target), key, Mode::NoLimit);
    }
    if (user != user_.global.end())
        return userValue(key, user->second);
    return fromDefinitions(kGlobal, key);
}

std::optional<formula::Value> StackEvaluator::resolveTrain(int scope, std::string_view key, Mode mode) {
    const Scope& s = *scopes_[static_cast<std::size_t>(scope)];
    if (std::optional<formula::Value> own = scopeOwnValue(s, key))
        return own;
    if (mode == Mode::Normal) {
        if (std::optional<formula::Value> elsewhere = valueFromElsewhere(scope, key))
            return elsewhere;
    }
    if (std::optional<formula::Value> user = trainUserValue(s.extruder, key))
        return user;
    if (s.is_mesh && s.mesh_user.empty())
        return resolve(extruderScope(s.extruder), key, mode);
    return fromDefinitions(scope, key);
}

std::optional<formula::Value> StackEvaluator::scopeOwnValue(const Scope& s, std::string_view key) const {
    if (s.is_mesh) {
        if (auto it = s.mesh_user.find(key); it != s.mesh_user.end())
            return userValue(key, it->second);
    } else if (key == "extruder_nr") {
        return formula::Value(static_cast<std::int64_t>(s.extruder));  // every train knows its number
    }
    return std::nullopt;
}

std::optional<formula::Value> StackEvaluator::valueFromElsewhere(int scope, std::string_view key) {
    const Scope& s = *scopes_[static_cast<std::size_t>(scope)];
    const SettingDefinition* def = definitions_.find(key);
    if (!def)
        return std::nullopt;
    const bool per_scope = def->settable_per_extruder || (s.is_mesh && def->settable_per_mesh);
    if (!per_scope && !extruderOwn(s.extruder, key))
        return resolve(kGlobal, key, Mode::Normal);
    if (!def->limit_to_extruder)
        return std::nullopt;
    const std::optional<int> target = limitTarget(scope, *def);
    if (!target)
        return std::nullopt;
    // The scope's own train: only a mesh without values of its own takes that train's value here.
    if (*target != s.extruder || (s.is_mesh && s.mesh_user.empty()))
        return resolve(extruderScope(*target), key, Mode::NoLimit);
    return std::nullopt;
}

std::optional<formula::Value> StackEvaluator::trainUserValue(int extruder, std::string_view key) const {
    if (auto train = user_.extruders.find(extruder); train != user_.extruders.end()) {
        if (auto it = train->second.find(key); it != train->second.end())
            return userValue(key, it->second);
    }
    // A command-line -s value wins over every profile, with --profiles too: Cura's own global user
    // container sits under the train's containers, but Cura writes a per-extruder value the user sets
    // into the train's user container, so what the user sets is what prints.
    if (auto it = user_.global.find(key); it != user_.global.end())
        return userValue(key, it->second);
    return std::nullopt;
}

std::optional<formula::Value> StackEvaluator::fromContainers(int scope,
                                                             const std::vector<InstanceContainer>& containers,
                                                             std::string_view key) {
    for (const InstanceContainer& container : containers) {
        auto it = container.values.find(key);
        if (it == container.values.end())
            continue;
        if (it->second.is_formula)
            return evaluateFormula(scope, key, it->second.text);
        return userValue(key, it->second.text);
    }
    return std::nullopt;
}

std::optional<formula::Value> StackEvaluator::fromDefinitions(int scope, std::string_view key) {
    const int extruder = scopes_[static_cast<std::size_t>(scope)]->extruder;
    const SettingDefinition* def = definitions_.find(key);
    const SettingDefinition* own = extruder >= 0 ? extruderOwn(extruder, key) : nullptr;
    const std::string type = def ? def->type : (own ? own->type : std::string());
    if (profiles_ && extruder >= 0) {
        if (auto it = profiles_->extruders.find(extruder); it != profiles_->extruders.end()) {
            if (auto v = fromContainers(scope, it->second, key))
                return v;
        }
    }
    // An extruder definition's entry without type or default (an override of a property only)
    // leaves the value to the machine definition.
    if (own && (own->value_formula || !own->default_value.empty() || !own->type.empty()))
        return definitionValue(scope, key, *own, type);
    if (!def)
        return std::nullopt;
    if (extruder >= 0 && cura_) {  // Cura: the global stack's user container, under the train's
        if (auto it = user_.global.find(key); it != user_.global.end())
            return userValue(key, it->second);
    }
    if (profiles_) {
        if (auto v = fromContainers(scope, profiles_->global, key))
            return v;
    }
    return definitionValue(scope, key, *def, type);
}

formula::Value StackEvaluator::definitionValue(int scope, std::string_view key,
                                               const SettingDefinition& source, const std::string& type) {
    if (source.value_formula)
        return evaluateFormula(scope, key, *source.value_formula);
    return typedValue(key, type, source.default_value);
}

std::optional<int> StackEvaluator::limitTarget(int scope, const SettingDefinition& def) {
    const formula::Value v = evaluateFormula(scope, def.key + ".limit_to_extruder", *def.limit_to_extruder);
    if (cura_)
        return curaExtruderIndex(v, scope == kGlobal);
    std::optional<long long> n = asInteger(v);
    if (!n || *n >= extruder_count_ || (*n < 0 && scope != kGlobal))
        return std::nullopt;
    return *n < 0 ? 0 : static_cast<int>(*n);  // the global scope reads a negative target as train 0
}

std::optional<int> StackEvaluator::curaExtruderIndex(const formula::Value& limit, bool global) const {
    if (isMinusOne(limit))
        return 0;  // the default extruder position: the first (every train counts as enabled)
    // Compared as str(): the string "-1" of an optional_extruder setting means "no extruder".
    const std::string text = formula::toPythonStr(limit);
    long long n = 0;
    try {
        std::size_t used = 0;
        n = std::stoll(text, &used);
        if (used != text.size() || text == "-1")
            return std::nullopt;
    } catch (const std::exception&) {
        return std::nullopt;
    }
    if (global)  // GlobalStack: the text must name one of its extruders ("0", "1", ...)
        return n >= 0 && n < extruder_count_ && std::to_string(n) == text
                   ? std::optional<int>(static_cast<int>(n))
                   : std::nullopt;
    if (n < 0)  // ExtruderStack: extruderList[int(text)], Python indexing
        n += extruder_count_;
    return n >= 0 && n < extruder_count_ ? std::optional<int>(static_cast<int>(n)) : std::nullopt;
}

std::optional<formula::Value> StackEvaluator::callCuraFunction(std::string_view name,
                                                               const std::vector<formula::Value>& args) {
    if (name == "extruderValue" && cura_) {
        const std::string key = argumentKey(args, 1);
        return resolve(extruderScope(curaExtruderValueIndex(args.empty() ? formula::Value() : args[0])), key,
                       Mode::Raw);
    }
    if (name == "extruderValue") {
        std::optional<long long> n = args.empty() ? std::nullopt : asInteger(args[0]);
        const std::string key = argumentKey(args, 1);
        long long nr = n.value_or(0) < 0 ? 0 : n.value_or(0);
        if (nr >= extruder_count_)
            return resolve(kGlobal, key, Mode::Normal);
        return resolve(extruderScope(static_cast<int>(nr)), key, Mode::Raw);
    }
    if (name == "extruderValues") {
        const std::string key = argumentKey(args, 0);
        formula::List values;
        for (int e = 0; e < extruder_count_; ++e)
            values.push_back(resolve(extruderScope(e), key, Mode::Raw));
        return formula::Value(std::move(values));
    }
    if (name == "resolveOrValue")
        return resolve(kGlobal, argumentKey(args, 0), Mode::Normal);
    if (name == "defaultExtruderPosition")
        return formula::Value(std::string("0"));
    if (name == "anyExtruderWithMaterial" || name == "anyExtruderNrWithOrDefault") {
        const std::string key = argumentKey(args, 0);
        if (!anyDefinition(key))
            return formula::Value(std::int64_t{0});
        for (int e = 0; e < extruder_count_; ++e) {
            if (formula::truthy(resolve(extruderScope(e), key, Mode::Normal)))
                return formula::Value(std::int64_t{e});
        }
        return formula::Value(std::int64_t{0});
    }
    return std::nullopt;
}

int StackEvaluator::curaExtruderValueIndex(const formula::Value& position) const {
    if (isMinusOne(position))
        return 0;  // the default extruder position
    const std::optional<long long> n = asInteger(position);
    if (!n)
        throw InputError("extruderValue: extruder position '" + formula::toPythonStr(position) +
                         "' is not a number");
    long long index = *n < 0 ? *n + extruder_count_ : *n;  // extruderList[int(position)]
    if (index < 0 || index >= extruder_count_)
        index = 0;  // Cura: "that extruder is not available. Returning the result from extruder 0 instead"
    return static_cast<int>(index);
}

SettingValues StackEvaluator::allText(int scope) {
    const Scope& s = *scopes_[static_cast<std::size_t>(scope)];
    std::vector<std::string> keys;
    for (const auto& [key, def] : definitions_.settings)
        keys.push_back(key);
    if (s.extruder >= 0) {
        keys.push_back("extruder_nr");
        const ExtruderDefinition* own =
            definitions_.extruders.empty() ? nullptr : &definitions_.extruders.front();
        for (const ExtruderDefinition& e : definitions_.extruders) {
            if (e.position == s.extruder)
                own = &e;
        }
        if (own) {
            for (const auto& [key, def] : own->overrides)
                keys.push_back(key);
        }
    }
    for (const auto& [key, text] : user_.global)
        keys.push_back(key);
    if (auto it = user_.extruders.find(s.extruder); s.extruder >= 0 && it != user_.extruders.end()) {
        for (const auto& [key, text] : it->second)
            keys.push_back(key);
    }
    for (const auto& [key, text] : s.mesh_user)
        keys.push_back(key);

    SettingValues out;
    for (const std::string& key : keys) {
        if (out.count(key))
            continue;
        try {
            out.emplace(key, textFromValue(resolve(scope, key, Mode::Normal)));
        } catch (const UserValueError&) {
            throw;
        } catch (const InputError& e) {
            const SettingDefinition* def = anyDefinition(key);
            if (!def)
                throw;
            // once: the same formula fails in every scope, and for every formula that reads it
            if (std::find(failures_.begin(), failures_.end(), e.what()) == failures_.end())
                failures_.push_back(e.what());
            out.emplace(key, def->default_value);
        }
    }
    return out;
}

}  // namespace mixengine
