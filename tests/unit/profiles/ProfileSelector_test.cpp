// Choosing Cura's profile containers (settings/profiles/ProfileSelector.h) on Cura's real resources:
// the defaults of a printer without and with nozzle variants, explicit names, errors, and the
// container ids real Cura 4.13 chose in the recorded fixtures (tests/data/cura_slice).
#include "settings/profiles/ProfileSelector.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>

#include "settings/Resolver.h"
#include "unit/settings/ScratchDir.h"

namespace mixengine {
namespace {

using unit::contains;
using unit::inputErrorOf;

bool curaInstalled() {
    return std::filesystem::is_directory("/usr/share/cura/resources/quality") &&
           std::filesystem::is_directory("/usr/share/cura/resources/materials");
}

/// Loaded once per machine: reading every profile file takes a moment.
struct Machine {
    DefinitionSet definitions;
    ProfileResources resources;
};

const Machine& machine(const std::string& id) {
    static std::map<std::string, std::unique_ptr<Machine>> cache;
    auto& slot = cache[id];
    if (!slot) {
        slot = std::make_unique<Machine>();
        const auto search = defaultSearchPath(nullptr);
        slot->definitions = loadDefinitionSet(id, search);
        const std::string quality_definition = slot->definitions.metadata.count("quality_definition")
                                                   ? slot->definitions.metadata.at("quality_definition")
                                                   : id;
        slot->resources = loadProfileResources(profileRoots(search), {id, quality_definition, "fdmprinter"});
    }
    return *slot;
}

ProfileStack select(const std::string& id, ProfileSelection selection) {
    selection.enabled = true;
    return selectProfiles(machine(id).definitions, selection, machine(id).resources);
}

/// "type:id" of each container, top first.
std::vector<std::string> ids(const std::vector<InstanceContainer>& containers) {
    std::vector<std::string> out;
    for (const InstanceContainer& c : containers)
        out.push_back(c.type + ":" + c.id);
    return out;
}

std::string valueIn(const std::vector<InstanceContainer>& containers, const std::string& type,
                    const std::string& key) {
    for (const InstanceContainer& c : containers) {
        auto it = c.values.find(key);
        if (c.type == type && it != c.values.end())
            return (it->second.is_formula ? "=" : "") + it->second.text;
    }
    return "<absent>";
}

class ProfileSelect : public ::testing::Test {
  protected:
    void SetUp() override {
        if (!curaInstalled())
            GTEST_SKIP() << "Cura resources not installed";
    }
};

TEST_F(ProfileSelect, Ender3Defaults) {
    const ProfileStack stack = select("creality_ender3", {});
    EXPECT_EQ(ids(stack.global), std::vector<std::string>{"quality:base_global_standard"});
    ASSERT_EQ(stack.extruders.size(), 1u);
    EXPECT_EQ(
        ids(stack.extruders.at(0)),
        (std::vector<std::string>{"quality:base_0.4_PLA_standard", "material:generic_pla_175_creality_ender3",
                                  "variant:creality_ender3_0.4"}));
    EXPECT_EQ(valueIn(stack.global, "quality", "layer_height"), "0.2");
    EXPECT_EQ(valueIn(stack.global, "quality", "top_bottom_thickness"), "=layer_height_0+layer_height*3");
    EXPECT_EQ(valueIn(stack.extruders.at(0), "material", "default_material_print_temperature"), "200");
    EXPECT_EQ(valueIn(stack.extruders.at(0), "material", "default_material_bed_temperature"), "50");
    EXPECT_EQ(valueIn(stack.extruders.at(0), "variant", "machine_nozzle_size"), "0.4");
}

TEST_F(ProfileSelect, Ender3ByNames) {
    // "Generic PLA" on a 1.75 mm printer is generic_pla_175; generic_pla itself is excluded there
    for (const char* material :
         {"generic_pla", "generic_pla_175", "Generic PLA", "generic_pla_175_creality_ender3"}) {
        const ProfileStack stack =
            select("creality_ender3", {true, "0.4mm Nozzle", material, "standard", ""});
        EXPECT_EQ(stack.extruders.at(0).at(1).id, "generic_pla_175_creality_ender3") << material;
    }
    const ProfileStack fine = select("creality_ender3", {true, "0.4mm", "generic_petg", "super", ""});
    EXPECT_EQ(ids(fine.global), std::vector<std::string>{"quality:base_global_super"});
    EXPECT_EQ(fine.extruders.at(0).at(0).id, "base_0.4_PETG_super");
    EXPECT_EQ(fine.extruders.at(0).at(1).id, "generic_petg_175_creality_ender3");
    EXPECT_EQ(valueIn(fine.global, "quality", "layer_height"), "0.12");
}

TEST_F(ProfileSelect, UltimakerS5Defaults) {
    const ProfileStack stack = select("ultimaker_s5", {});
    EXPECT_EQ(ids(stack.global), std::vector<std::string>{"quality:um_s5_global_Normal_Quality"});
    ASSERT_EQ(stack.extruders.size(), 2u);
    for (int e = 0; e < 2; ++e) {
        EXPECT_EQ(ids(stack.extruders.at(e)),
                  (std::vector<std::string>{"quality:um_s5_aa0.4_PLA_Normal_Quality",
                                            "material:generic_pla_ultimaker_s5_AA_0.4",
                                            "variant:ultimaker_s5_aa04"}));
    }
    EXPECT_EQ(valueIn(stack.extruders.at(0), "material", "cool_fan_speed"), "100");
    EXPECT_EQ(valueIn(stack.extruders.at(0), "variant", "machine_nozzle_id"), "AA 0.4");
}

TEST_F(ProfileSelect, UltimakerS5PerExtruderAndIntent) {
    const ProfileStack mixed =
        select("ultimaker_s5", {true, "AA 0.4,BB 0.4", "generic_pla,generic_pva", "", ""});
    EXPECT_EQ(mixed.extruders.at(1).at(0).id, "um_s5_bb0.4_PVA_Normal_Quality");
    EXPECT_EQ(mixed.extruders.at(1).at(1).id, "generic_pva_ultimaker_s5_BB_0.4");
    EXPECT_EQ(mixed.extruders.at(1).at(2).id, "ultimaker_s5_bb04");

    const ProfileStack intent = select("ultimaker_s5", {true, "", "", "fast", "engineering"});
    EXPECT_EQ(ids(intent.global), std::vector<std::string>{"quality:um_s5_global_Fast_Quality"});
    EXPECT_EQ(ids(intent.extruders.at(0)).front(), "intent:um_s5_aa0.4_PLA_Fast_Print_Accurate");
    // an intent id selects its quality type too
    const ProfileStack by_id =
        select("ultimaker_s5", {true, "", "", "", "um_s5_aa0.4_PLA_Fast_Print_Accurate"});
    EXPECT_EQ(ids(by_id.global), std::vector<std::string>{"quality:um_s5_global_Fast_Quality"});
    EXPECT_EQ(by_id.extruders.at(1).at(0).id, "um_s5_aa0.4_PLA_Fast_Print_Accurate");
}

TEST_F(ProfileSelect, QualityFollowsWhatIsAvailable) {
    // the 1.0 mm nozzle only has "draft" profiles: Cura drops "standard" for the first available type
    const ProfileStack wide = select("creality_ender3", {true, "1.0mm", "", "", ""});
    EXPECT_EQ(ids(wide.global), std::vector<std::string>{"quality:base_global_draft"});
    EXPECT_EQ(wide.extruders.at(0).at(0).id, "base_1.0_PLA_draft");
    // a quality type the global stack has but the material has not is not available
    const std::string message = inputErrorOf([] {
        select("creality_ender3", {true, "", "generic_tpu", "low", ""});
    });
    EXPECT_TRUE(contains(message, "available: adaptive, standard, super")) << message;
    // a quality container id selects its type
    const ProfileStack by_id = select("creality_ender3", {true, "", "", "base_0.4_PLA_super", ""});
    EXPECT_EQ(ids(by_id.global), std::vector<std::string>{"quality:base_global_super"});
}

TEST_F(ProfileSelect, MachineWithoutMachineQualities) {
    const ProfileStack stack = select("prusa_i3_mk3", {});
    EXPECT_EQ(ids(stack.global), std::vector<std::string>{"quality:normal"});
    EXPECT_EQ(ids(stack.extruders.at(0)),
              (std::vector<std::string>{"quality:normal", "material:generic_pla_175"}));
}

TEST_F(ProfileSelect, UnknownNamesListWhatExists) {
    std::string message = inputErrorOf([] { select("creality_ender3", {true, "", "", "ultrafine", ""}); });
    EXPECT_TRUE(contains(message, "--quality 'ultrafine'")) << message;
    EXPECT_TRUE(contains(message, "standard")) << message;
    message = inputErrorOf([] { select("ultimaker_s5", {true, "AA 9.9", "", "", ""}); });
    EXPECT_TRUE(contains(message, "AA 0.4")) << message;
    message = inputErrorOf([] { select("creality_ender3", {true, "", "unobtainium", "", ""}); });
    EXPECT_TRUE(contains(message, "no such material")) << message;
    EXPECT_TRUE(contains(message, "generic_pla_175")) << message;
    message = inputErrorOf([] { select("creality_ender3", {true, "", "", "", "engineering"}); });
    EXPECT_TRUE(contains(message, "--intent 'engineering'")) << message;
    message = inputErrorOf([] { select("prusa_i3_mk3", {true, "0.4mm", "", "", ""}); });
    EXPECT_TRUE(contains(message, "no nozzle variants")) << message;
    message = inputErrorOf([] { select("creality_ender3", {true, "0.4mm,0.6mm", "", "", ""}); });
    EXPECT_TRUE(contains(message, "2 names for 1 extruder")) << message;
}

TEST_F(ProfileSelect, UnknownKeysAreDropped) {
    // longer_0.4_PETG_standard has "#retraction_extra_prime_amount = 0.5", a commented-out line
    const ProfileStack stack = select("longer_lk5", {true, "", "generic_petg", "standard", ""});
    for (const InstanceContainer& c : stack.extruders.at(0))
        EXPECT_EQ(c.values.count("#retraction_extra_prime_amount"), 0u) << c.id;
}

/// A fixture's job as a ProfileSelection (tests/e2e/jobs: names as strings or per position).
std::string jobNames(const nlohmann::json& job, const char* key) {
    if (!job.contains(key))
        return "";
    if (job[key].is_string())
        return job[key];
    std::string out;
    for (std::size_t i = 0; i < job[key].size(); ++i)
        out += (i ? "," : "") + job[key].value(std::to_string(i), std::string());
    return out;
}

TEST_F(ProfileSelect, SameContainersAsRecordedCura) {
    const std::filesystem::path fixtures = std::filesystem::path(MIXENGINE_TEST_DATA_DIR) / "cura_slice";
    const std::filesystem::path jobs = std::filesystem::path(MIXENGINE_SOURCE_DIR) / "tests/e2e/jobs";
    int compared = 0;
    for (const auto& entry : std::filesystem::directory_iterator(fixtures)) {
        if (entry.path().extension() != ".json" || !std::filesystem::exists(jobs / entry.path().filename()))
            continue;
        const nlohmann::json fixture = nlohmann::json::parse(std::ifstream(entry.path()));
        const nlohmann::json job = nlohmann::json::parse(std::ifstream(jobs / entry.path().filename()));
        ProfileSelection selection{true, jobNames(job, "variant"), jobNames(job, "material"),
                                   job.value("quality", ""), job.value("intent", "")};
        const ProfileStack stack = select(job["machine"], selection);
        const std::string name = entry.path().filename().string();
        EXPECT_EQ(stack.global.empty() ? "empty_quality" : stack.global.front().id,
                  fixture["containers"]["global"]["quality"])
            << name;
        const auto& extruders = fixture["containers"]["extruders"];
        for (std::size_t e = 0; e < extruders.size(); ++e) {
            std::map<std::string, std::string> chosen = {{"intent", "empty_intent"},
                                                         {"quality", "empty_quality"},
                                                         {"material", "empty_material"},
                                                         {"variant", "empty_variant"}};
            for (const InstanceContainer& c : stack.extruders.at(static_cast<int>(e)))
                chosen[c.type] = c.id;
            for (const char* type : {"intent", "quality", "material", "variant"})
                EXPECT_EQ(chosen[type], extruders[e][type]) << name << " extruder " << e << " " << type;
        }
        ++compared;
    }
    if (compared == 0)
        GTEST_SKIP() << "no fixtures in " << fixtures;
}

}  // namespace
}  // namespace mixengine
