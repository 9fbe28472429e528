// Cura's material files (settings/profiles/MaterialProfile.h, XmlScan.h): the setting map of
// XmlMaterialProfile, machine and hotend blocks, and the containers derived for one machine.
#include "settings/profiles/MaterialProfile.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "settings/profiles/XmlScan.h"
#include "unit/settings/ScratchDir.h"

namespace mixengine {
namespace {

using unit::contains;
using unit::inputErrorOf;

const std::filesystem::path kMaterials = "/usr/share/cura/resources/materials";

const MaterialContainer* containerWithId(const std::vector<MaterialContainer>& list, const std::string& id) {
    for (const MaterialContainer& c : list) {
        if (c.id == id)
            return &c;
    }
    return nullptr;
}

std::string valueOr(const MaterialValues& values, const std::string& key) {
    auto it = values.find(key);
    return it == values.end() ? "<absent>" : it->second;
}

constexpr const char* kSmall = R"(<?xml version="1.0" encoding="UTF-8"?>
<!-- a comment -->
<fdmmaterial xmlns="http://www.ultimaker.com/material" xmlns:cura="http://www.ultimaker.com/cura" version="1.3">
  <metadata>
    <name><brand>Acme &amp; Co</brand><material>PETG</material><color>Blue</color></name>
    <GUID>1234</GUID>
  </metadata>
  <properties><density>1.27</density><diameter>1.75</diameter></properties>
  <settings>
    <setting key="print temperature">235</setting>
    <setting key="heated bed temperature">80</setting>
    <setting key="processing temperature graph"><point flow="2" temperature="180"/><point flow="10.5" temperature="230"/></setting>
    <setting key="unknown thing">7</setting>
    <cura:setting key="material_crystallinity">yes</cura:setting>
    <machine>
      <machine_identifier manufacturer="Acme" product="Ultimaker 3 Extended"/>
      <machine_identifier manufacturer="Acme" product="acme_box"/>
      <setting key="print cooling">50</setting>
      <hotend id="AA 0.4"><setting key="hardware compatible">no</setting><setting key="retraction amount">4</setting></hotend>
    </machine>
  </settings>
</fdmmaterial>
)";

TEST(ProfileMaterial, MetadataAndSettingMap) {
    const MaterialProfile p = parseMaterialProfile(kSmall, "acme_petg", "acme_petg.xml.fdm_material");
    EXPECT_EQ(p.base_file, "acme_petg");
    EXPECT_EQ(p.brand, "Acme & Co");
    EXPECT_EQ(p.material, "PETG");
    EXPECT_EQ(p.name, "Blue PETG");
    EXPECT_EQ(p.guid, "1234");
    EXPECT_EQ(p.approximate_diameter, 2);
    EXPECT_EQ(valueOr(p.values, "default_material_print_temperature"), "235");
    EXPECT_EQ(valueOr(p.values, "default_material_bed_temperature"), "80");
    EXPECT_EQ(valueOr(p.values, "material_flow_temp_graph"), "[[2.0, 180.0], [10.5, 230.0]]");
    EXPECT_EQ(valueOr(p.values, "material_diameter"), "1.75");
    EXPECT_EQ(valueOr(p.values, "material_guid"), "1234");
    EXPECT_EQ(valueOr(p.values, "material_crystallinity"), "True");
    EXPECT_EQ(p.values.size(), 6u);  // "unknown thing" is not mapped
}

TEST(ProfileMaterial, MachineAndHotendContainers) {
    const MaterialProfile p = parseMaterialProfile(kSmall, "acme_petg", "test");
    const auto um3e = materialContainersFor(p, "ultimaker3_extended");
    ASSERT_EQ(um3e.size(), 3u);  // base, machine, hotend
    EXPECT_EQ(um3e[0].id, "acme_petg");
    EXPECT_EQ(um3e[0].definition, "fdmprinter");
    EXPECT_EQ(valueOr(um3e[0].values, "cool_fan_speed"), "<absent>");
    EXPECT_EQ(um3e[1].id, "acme_petg_ultimaker3_extended");
    EXPECT_EQ(valueOr(um3e[1].values, "cool_fan_speed"), "50");
    EXPECT_EQ(valueOr(um3e[1].values, "default_material_print_temperature"), "235");
    EXPECT_TRUE(um3e[1].compatible);
    EXPECT_EQ(um3e[2].id, "acme_petg_ultimaker3_extended_AA_0.4");
    EXPECT_EQ(um3e[2].variant_name, "AA 0.4");
    EXPECT_EQ(valueOr(um3e[2].values, "retraction_amount"), "4");
    EXPECT_EQ(valueOr(um3e[2].values, "cool_fan_speed"), "50");
    EXPECT_FALSE(um3e[2].compatible);
    // a product without an entry in product_to_id.json is matched by its name
    EXPECT_EQ(materialContainersFor(p, "acme_box").size(), 3u);
    EXPECT_EQ(materialContainersFor(p, "creality_ender3").size(), 1u);
}

TEST(ProfileMaterial, ProductNamesToDefinitionIds) {
    EXPECT_EQ(productDefinitionIds("Ultimaker S5"), std::vector<std::string>{"ultimaker_s5"});
    const auto guessed = productDefinitionIds("Weedo X40");
    EXPECT_NE(std::find(guessed.begin(), guessed.end(), "weedo_x40"), guessed.end());
    const auto digits = productDefinitionIds("Foo 3 Max");
    EXPECT_NE(std::find(digits.begin(), digits.end(), "foo3_max"), digits.end());
    EXPECT_NE(std::find(digits.begin(), digits.end(), "foo_3_max"), digits.end());
}

TEST(ProfileMaterial, GenericPlaFile) {
    if (!std::filesystem::exists(kMaterials / "generic_pla.xml.fdm_material"))
        GTEST_SKIP() << "fdm-materials not installed";
    const MaterialProfile pla = readMaterialFile(kMaterials / "generic_pla.xml.fdm_material");
    EXPECT_EQ(pla.base_file, "generic_pla");
    EXPECT_EQ(pla.brand, "Generic");
    EXPECT_EQ(pla.material, "PLA");
    EXPECT_EQ(pla.name, "PLA");
    EXPECT_EQ(pla.guid, "506c9f0d-e3aa-4bd4-b2d2-23e2425b1aa9");
    EXPECT_EQ(pla.approximate_diameter, 3);
    EXPECT_EQ(valueOr(pla.values, "material_diameter"), "2.85");
    EXPECT_EQ(valueOr(pla.values, "default_material_print_temperature"), "200");
    EXPECT_EQ(valueOr(pla.values, "default_material_bed_temperature"), "60");
    EXPECT_EQ(valueOr(pla.values, "material_standby_temperature"), "175");
    EXPECT_EQ(valueOr(pla.values, "build_volume_temperature"), "28");

    const auto s5 = materialContainersFor(pla, "ultimaker_s5");
    const MaterialContainer* aa04 = containerWithId(s5, "generic_pla_ultimaker_s5_AA_0.4");
    ASSERT_NE(aa04, nullptr);
    EXPECT_EQ(valueOr(aa04->values, "cool_fan_speed"), "100");
    const MaterialContainer* cc04 = containerWithId(s5, "generic_pla_ultimaker_s5_CC_0.4");
    ASSERT_NE(cc04, nullptr);
    EXPECT_EQ(valueOr(cc04->values, "material_standby_temperature"), "100");
    // only "yes"/"no" become True/False; other text stays as written, as in the plugin
    EXPECT_EQ(valueOr(cc04->values, "material_crystallinity"), "true");

    const auto um2 = materialContainersFor(pla, "ultimaker2");
    const MaterialContainer* um2_machine = containerWithId(um2, "generic_pla_ultimaker2");
    ASSERT_NE(um2_machine, nullptr);
    EXPECT_EQ(valueOr(um2_machine->values, "material_flow_temp_graph"), "[[2.0, 180.0], [10.0, 230.0]]");
}

TEST(ProfileMaterial, GenericPla175ForTheEnder3) {
    if (!std::filesystem::exists(kMaterials / "generic_pla_175.xml.fdm_material"))
        GTEST_SKIP() << "fdm-materials not installed";
    const MaterialProfile pla = readMaterialFile(kMaterials / "generic_pla_175.xml.fdm_material");
    EXPECT_EQ(pla.approximate_diameter, 2);
    const auto ender = materialContainersFor(pla, "creality_ender3");
    const MaterialContainer* c = containerWithId(ender, "generic_pla_175_creality_ender3");
    ASSERT_NE(c, nullptr);
    EXPECT_EQ(valueOr(c->values, "default_material_print_temperature"), "200");
    EXPECT_EQ(valueOr(c->values, "default_material_bed_temperature"), "50");
    EXPECT_EQ(valueOr(c->values, "retraction_amount"), "5");
    EXPECT_EQ(valueOr(c->values, "material_diameter"), "1.75");
}

TEST(ProfileMaterial, EveryInstalledFileParses) {
    if (!std::filesystem::is_directory(kMaterials))
        GTEST_SKIP() << "fdm-materials not installed";
    int count = 0;
    for (const auto& entry : std::filesystem::directory_iterator(kMaterials)) {
        if (!entry.path().string().ends_with(".xml.fdm_material"))
            continue;
        EXPECT_NO_THROW(readMaterialFile(entry.path())) << entry.path();
        ++count;
    }
    EXPECT_GT(count, 200);
}

TEST(ProfileMaterial, MalformedXmlNamesFileAndLine) {
    const std::string message = inputErrorOf([] {
        parseMaterialProfile(
            "<fdmmaterial xmlns=\"http://www.ultimaker.com/material\">\n<metadata>\n</fdmmaterial>", "bad",
            "bad.xml.fdm_material");
    });
    EXPECT_TRUE(contains(message, "bad.xml.fdm_material:3")) << message;
    EXPECT_TRUE(contains(inputErrorOf([] { parseXml("<a>&bogus;</a>", "f.xml"); }), "bogus"));
}

TEST(ProfileMaterial, XmlNamespacesAndText) {
    const XmlElement root = parseXml(
        "<r xmlns='urn:a' xmlns:b='urn:b'><b:x k=\"1 &lt; 2\">t&#65;<![CDATA[<raw>]]></b:x><y/></r>", "t");
    EXPECT_EQ(root.ns, "urn:a");
    ASSERT_NE(root.child("urn:b", "x"), nullptr);
    EXPECT_EQ(*root.child("urn:b", "x")->attribute("k"), "1 < 2");
    EXPECT_EQ(root.child("urn:b", "x")->text, "tA<raw>");
    EXPECT_NE(root.child("urn:a", "y"), nullptr);
    EXPECT_EQ(root.child("urn:b", "y"), nullptr);
}

}  // namespace
}  // namespace mixengine
