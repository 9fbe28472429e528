#pragma once
// Cura's setting stack, evaluated: the value of every setting in every scope as Cura 4.13 would
// compute it, `value` / `resolve` / `limit_to_extruder` formulas included.
//
// Scopes and the order in which a key is looked up (first hit wins):
//   global       the `resolve` formula (unless the user set the key); the value of the extruder
//                named by `limit_to_extruder` (settable-per-extruder keys only); user -s values; the
//                global profile containers; the machine definition's `value` formula, else its
//                `default_value`.
//   extruder N   keys that are not settable per extruder: the global value. Otherwise the value of
//                the extruder named by `limit_to_extruder` when it is another one (looked up there
//                without limiting again, so never recursively); -eN user values; global user
//                values; the extruder's profile containers (settings/ProfileStack.h); the extruder
//                definition's value; the global profile containers; the machine definition's value.
//   mesh         its own user values; the extruder named by `limit_to_extruder`; then as its
//                extruder train, with formulas evaluated in the mesh's scope so that a per-mesh
//                value (e.g. infill_sparse_density) flows into the keys computed from it.
// Formulas are evaluated in the scope that asked ("the root stack", as in Cura), lazily, with
// memoisation and cycle detection. Cura's functions extruderValue, extruderValues,
// resolveOrValue, defaultExtruderPosition, anyExtruderWithMaterial and
// anyExtruderNrWithOrDefault are provided; every extruder counts as enabled.
//
// Cura's frontend (ProfileStack::cura, i.e. --profiles) differs where Cura's stacks (Uranium's
// ContainerStack, cura/Settings/GlobalStack.py, ExtruderStack.py, CuraFormulaFunctions.py) differ
// from CuraEngine's command line:
//   - values keep Python's literal types (curaValueFromText): "235" is an int, extruder-typed
//     values are strings, a material's "true" stays text; so the text is what Cura sends;
//   - a limit_to_extruder value equal to the number -1 means the default extruder (0), but the
//     string "-1" (an optional_extruder setting left at its default, e.g. infill_extruder_nr)
//     means no limit: the global scope then keeps its own value, it does not read train 0's;
//   - in a train, the global user values still come first: Cura's global user container sits in the
//     next stack, under the train's containers, but Cura writes what a user sets for an extruder into
//     that train's user container, so a command-line -s value wins over every profile as the user meant;
//   - an extruder definition's override of a key its chain does not declare is ignored
//     (ExtruderDefinition::undeclared);
//   - extruderValue(n, key): n == -1 → train 0, a negative n counts from the last train (Python
//     indexing), a train that does not exist → train 0.
// Errors: a cycle, or a formula that fails, is an InputError naming the setting and the formula.
// allText() evaluates every key; a failing *definition* formula there falls back to the
// definition's default_value and is reported in failures() instead of stopping the slice.
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "common/Error.h"
#include "settings/DefinitionSet.h"
#include "settings/ProfileStack.h"
#include "settings/Resolver.h"
#include "settings/formula/Expression.h"
#include "settings/formula/Value.h"

namespace mixengine {

/// A value the user gave (-s, or Cura's message) that does not fit its setting's type.
class UserValueError : public InputError {
  public:
    using InputError::InputError;
};

class StackEvaluator {
  public:
    StackEvaluator(const DefinitionSet& definitions, const UserSettings& user, int extruder_count,
                   const ProfileStack* profiles = nullptr);
    ~StackEvaluator();
    StackEvaluator(const StackEvaluator&) = delete;
    StackEvaluator& operator=(const StackEvaluator&) = delete;

    static constexpr int kGlobal = 0;
    static int extruderScope(int extruder_nr) { return 1 + extruder_nr; }
    int extruderCount() const { return extruder_count_; }

    /// Adds a mesh scope on top of extruder train `extruder`; returns its scope id.
    int addMeshScope(SettingValues user, int extruder);

    /// The value of `key` in `scope`; nullopt when no definition and no user value has it.
    std::optional<formula::Value> value(int scope, std::string_view key);

    /// The setting's `enabled` formula in `scope`: whether Cura shows it with these values. True when
    /// it has none, or when the formula cannot be evaluated here.
    bool enabled(int scope, std::string_view key);
    /// Every key known in `scope` (definitions and user values) as text.
    SettingValues allText(int scope);

    /// "setting: formula: problem" lines for definition formulas that failed in allText().
    const std::vector<std::string>& failures() const { return failures_; }

  private:
    struct Scope;
    class ScopeEnvironment;
    enum class Mode { Normal, NoLimit, Raw };

    formula::Value resolve(int scope, std::string_view key, Mode mode);
    std::optional<formula::Value> resolveGlobal(std::string_view key, Mode mode);
    std::optional<formula::Value> resolveTrain(int scope, std::string_view key, Mode mode);
    // The rules of a train or mesh scope, in resolveTrain's order (see the top of this file); each
    // gives nullopt when it does not apply.
    /// A mesh's own user value; a train's extruder_nr.
    std::optional<formula::Value> scopeOwnValue(const Scope& s, std::string_view key) const;
    /// (Mode::Normal) the global value of a key not settable in the scope; the value of the
    /// extruder named by limit_to_extruder, unless that is the scope's own train.
    std::optional<formula::Value> valueFromElsewhere(int scope, std::string_view key);
    /// -eN user values, then global user values.
    std::optional<formula::Value> trainUserValue(int extruder, std::string_view key) const;
    std::optional<formula::Value> fromDefinitions(int scope, std::string_view key);
    /// `source`'s value formula evaluated in `scope`, else its default_value read as `type`.
    formula::Value definitionValue(int scope, std::string_view key, const SettingDefinition& source,
                                   const std::string& type);
    /// The train a `limit_to_extruder` formula sends `def` to from `scope`, or nullopt (no limit).
    std::optional<int> limitTarget(int scope, const SettingDefinition& def);
    /// (Cura) GlobalStack / ExtruderStack's reading of a limit_to_extruder value.
    std::optional<int> curaExtruderIndex(const formula::Value& limit, bool global) const;
    /// (Cura) the train extruderValue(position, ...) reads (CuraFormulaFunctions.getValueInExtruder).
    int curaExtruderValueIndex(const formula::Value& position) const;
    /// Text → value: valueFromText, or curaValueFromText (Python's literal types) for Cura's stacks.
    formula::Value typedValue(std::string_view key, const std::string& type, std::string_view text) const;
    formula::Value evaluateFormula(int scope, std::string_view key, const std::string& formula);
    formula::Value userValue(std::string_view key, const std::string& text) const;
    std::optional<formula::Value> callCuraFunction(std::string_view name,
                                                   const std::vector<formula::Value>& args);
    const SettingDefinition* extruderOwn(int extruder, std::string_view key) const;
    const SettingDefinition* anyDefinition(std::string_view key) const;
    const formula::Expression& compiled(const std::string& formula);
    std::optional<formula::Value> fromContainers(int scope, const std::vector<InstanceContainer>& containers,
                                                 std::string_view key);

    const DefinitionSet& definitions_;
    const UserSettings& user_;
    const ProfileStack* profiles_;
    bool cura_;  ///< resolve as Cura's frontend (ProfileStack::cura)
    int extruder_count_;
    std::vector<std::unique_ptr<Scope>> scopes_;
    std::unordered_map<const std::string*, std::unique_ptr<formula::Expression>> expressions_;
    std::vector<std::string> failures_;
};

}  // namespace mixengine
