// The list of settings MixEngine does not act on yet (settings/NotHonoured.h): parsing, the
// embedded list, and which values are warned about.
#include "settings/NotHonoured.h"

#include <gtest/gtest.h>

#include <string>

#include "common/Error.h"

namespace mixengine {
namespace {

void define(SettingDefinitionMap& map, const std::string& key, const std::string& type,
            const std::string& value, std::optional<std::string> formula = std::nullopt) {
    SettingDefinition& def = map[key];
    def.key = key;
    def.type = type;
    def.default_value = value;
    def.value_formula = std::move(formula);
    def.settable_per_extruder = true;
    def.settable_per_mesh = true;
}

/// coasting_volume follows layer_height by formula; adhesion_type and ironing_enabled are plain.
DefinitionSet machine() {
    DefinitionSet set;
    set.machine_id = "test";
    define(set.settings, "layer_height", "float", "0.1");
    define(set.settings, "coasting_volume", "float", "0.064", "layer_height * 0.64");
    define(set.settings, "adhesion_type", "enum", "skirt");
    define(set.settings, "ironing_enabled", "bool", "False");
    define(set.settings, "raft_margin", "float", "15");
    set.settings["raft_margin"].enabled_formula = "adhesion_type == 'raft'";
    ExtruderDefinition extruder;
    extruder.id = "test_extruder_0";
    extruder.position = 0;
    set.extruders.push_back(std::move(extruder));
    return set;
}

const char* const kList = R"({"settings": {
    "coasting_volume": "coasting is not built",
    "adhesion_type": {"values": ["raft"], "why": "no raft"},
    "ironing_enabled": "no ironing",
    "raft_margin": "no raft"}})";

std::vector<std::string> warningsFor(UserSettings user) {
    return notHonouredWarnings(parseNotHonoured(kList, "test"), machine(), user, 1);
}

TEST(NotHonoured, ParsesReasonsAndValueEntries) {
    const std::vector<NotHonouredEntry> list = parseNotHonoured(kList, "test");
    ASSERT_EQ(list.size(), 4u);
    EXPECT_EQ(list[0].key, "adhesion_type");  // in key order
    EXPECT_EQ(list[0].values, std::vector<std::string>{"raft"});
    EXPECT_TRUE(list[1].values.empty());
    EXPECT_EQ(list[2].why, "no ironing");
}

TEST(NotHonoured, MalformedListNamesItsOrigin) {
    try {
        parseNotHonoured(R"({"settings": {"x": 3}})", "list.json");
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("list.json: entry 'x'"), std::string::npos) << e.what();
    }
    EXPECT_THROW(parseNotHonoured("{", "list.json"), InputError);
}

TEST(NotHonoured, NoWarningForTheDefinitionsValues) {
    EXPECT_TRUE(warningsFor({}).empty());
    EXPECT_TRUE(warningsFor({{{"adhesion_type", "brim"}}, {}}).empty());  // brim is honoured
    EXPECT_TRUE(warningsFor({{{"ironing_enabled", "False"}}, {}}).empty());
}

TEST(NotHonoured, AFormulaFollowingItsParentIsNotWarnedAbout) {
    // Cura sends coasting_volume = 0.128 computed from layer_height 0.2: the definitions give the same.
    EXPECT_TRUE(warningsFor({{{"layer_height", "0.2"}, {"coasting_volume", "0.128"}}, {}}).empty());
}

TEST(NotHonoured, ChangedValuesAreWarnedOnceWithTheExactText) {
    const std::vector<std::string> w = warningsFor(
        {{{"adhesion_type", "raft"}, {"coasting_volume", "0.5"}}, {{0, {{"ironing_enabled", "True"}}}}});
    ASSERT_EQ(w.size(), 3u);
    EXPECT_EQ(w[0], "setting 'adhesion_type' has no effect in MixEngine yet (value raft: no raft)");
    EXPECT_EQ(w[1],
              "setting 'coasting_volume' has no effect in MixEngine yet (value 0.5: coasting is not built)");
    EXPECT_EQ(w[2], "setting 'ironing_enabled' has no effect in MixEngine yet (value True: no ironing)");
}

TEST(NotHonoured, ASettingCuraHidesIsNotWarnedAbout) {
    // raft_margin is only enabled (shown, and read by CuraEngine) with a raft.
    EXPECT_TRUE(warningsFor({{{"raft_margin", "5"}}, {}}).empty());
    const std::vector<std::string> w = warningsFor({{{"raft_margin", "5"}, {"adhesion_type", "raft"}}, {}});
    ASSERT_EQ(w.size(), 2u);
    EXPECT_EQ(w[1], "setting 'raft_margin' has no effect in MixEngine yet (value 5.0: no raft)");
}

TEST(NotHonoured, TheEmbeddedListParsesAndNamesRealSettings) {
    const std::vector<NotHonouredEntry> list = embeddedNotHonoured();
    ASSERT_FALSE(list.empty());
    for (const NotHonouredEntry& entry : list) {
        EXPECT_FALSE(entry.key.empty());
        EXPECT_FALSE(entry.why.empty()) << entry.key;
    }
}

}  // namespace
}  // namespace mixengine

namespace mixengine {
namespace {

// "multi_extruder_only": the entry holds for prints with two or more extruder trains; a machine with one
// train is not warned.
TEST(NotHonoured, MultiExtruderOnlyEntriesNeedTwoTrains) {
    const char* const list =
        R"({"settings": {"ironing_enabled": {"why": "two nozzles", "multi_extruder_only": true}}})";
    const std::vector<NotHonouredEntry> entries = parseNotHonoured(list, "test");
    ASSERT_EQ(entries.size(), 1u);
    EXPECT_TRUE(entries[0].multi_extruder_only);
    EXPECT_TRUE(entries[0].values.empty());
    const UserSettings user{{{"ironing_enabled", "True"}}, {}};
    EXPECT_TRUE(notHonouredWarnings(entries, machine(), user, 1).empty());
    EXPECT_EQ(notHonouredWarnings(entries, machine(), user, 2).size(), 1u);
}

}  // namespace
}  // namespace mixengine
