// The mixing settings (mixing/setup/MixingSettings.h): defaults without the definition file, validation
// with one-line errors naming the setting, the formats of ratios and stops, and seed 001's aliases
// (settings/FrontendValues.h, withCanonicalKeys).
#include "mixing/setup/MixingSettings.h"

#include <gtest/gtest.h>

#include "../SettingsTestSupport.h"

#include "common/Error.h"
#include "settings/FrontendValues.h"

namespace mixengine {
namespace {

Settings scope(SettingValues values) {
    return test::defaultsWith("global settings", values);
}

/// The message of the InputError `f` throws ("" when it throws nothing).
template <typename F>
std::string errorOf(F f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(MixingSettings, WithoutTheDefinitionFileMixingIsOff) {
    const MixingOutput out = parseMixingOutput(scope({}));
    EXPECT_EQ(out.mode, MixingMode::Single);
    EXPECT_FALSE(out.enabled());
    // Everything else has code defaults too: a gradient needs nothing but the mode.
    const Settings s = scope({{"mixing_mode", "gradient"}});
    const MixingOutput on = parseMixingOutput(s);
    EXPECT_EQ(on.dialect, MixDialectKind::EbAxes);
    EXPECT_EQ(on.channels, 2);
    EXPECT_EQ(on.resolution_steps, 100);
    const MeshMixing m = parseMeshMixing(s, on);
    ASSERT_EQ(m.stops.size(), 2u);
    EXPECT_EQ(m.stops[0].height, 0.0);
    EXPECT_EQ(m.stops[1].height, 100.0);
    EXPECT_EQ(m.unit, HeightUnit::Percent);
    EXPECT_EQ(parseChamberVolumeMm3(s), 0.0);
    EXPECT_EQ(parseChannelColors(s, 2).size(), 2u);
}

TEST(MixingSettings, BadValuesNameTheSetting) {
    const auto output = [](SettingValues v) { return errorOf([&] { parseMixingOutput(scope(v)); }); };
    const auto mesh = [](SettingValues v) {
        return errorOf([&] {
            const Settings s = scope(v);
            parseMeshMixing(s, parseMixingOutput(s));
        });
    };
    EXPECT_EQ(output({{"mixing_mode", "rainbow"}}),
              "setting 'mixing_mode': unknown mode 'rainbow' (single, dual, gradient or color)");
    EXPECT_EQ(output({{"mixing_mode", "dual"}, {"mixing_dialect", "bambu"}}),
              "setting 'mixing_dialect': unknown dialect 'bambu' (one of eb_axes, klipper_b, rrf_colon, "
              "marlin_m163, marlin_m165, rrf_m567)");
    EXPECT_EQ(output({{"mixing_mode", "dual"}, {"mixing_dialect", "rrf_m567"}, {"mixing_channels", "6"}}),
              "setting 'mixing_channels': 6 is outside 1..5");
    EXPECT_EQ(output({{"mixing_mode", "dual"}, {"mixing_channels", "3"}}),
              "setting 'mixing_channels': 3 channels, but dialect eb_axes drives exactly 2 (E and B)");
    EXPECT_EQ(output({{"mixing_mode", "dual"},
                      {"mixing_dialect", "marlin_m163"},
                      {"mixing_channels", "4"},
                      {"machine_extruder_count", "3"}}),
              "setting 'mixing_channels': 4 channels, but the printer has 3 (machine_extruder_count)");
    EXPECT_EQ(output({{"mixing_mode", "dual"}, {"mixing_resolution", "0"}}),
              "setting 'mixing_resolution': 0 steps is outside 1..1000000");
    EXPECT_EQ(
        mesh({{"mixing_mode", "gradient"}, {"mixing_gradient_start", "80"}, {"mixing_gradient_end", "20"}}),
        "setting 'mixing_gradient_start': 80 is above mixing_gradient_end 20");
    EXPECT_EQ(mesh({{"mixing_mode", "dual"}, {"mixing_ratio", "0.3:0.6"}}),
              "setting 'mixing_ratio': ratios '0.3:0.6' add up to 0.9, not 1");
    EXPECT_EQ(mesh({{"mixing_mode", "dual"}, {"mixing_ratio", "0.2:0.3:0.5"}}),
              "setting 'mixing_ratio': '0.2:0.3:0.5' has more ratios than mixing_channels (2)");
    EXPECT_EQ(mesh({{"mixing_mode", "dual"}, {"mixing_ratio", "1.5:-0.5"}}),
              "setting 'mixing_ratio': '1.5:-0.5' has a negative ratio");
    EXPECT_EQ(mesh({{"mixing_mode", "gradient"}, {"mixing_gradient_stops", "0=1:0; 60=0:1; 40=1:0"}}),
              "setting 'mixing_gradient_stops': heights must not decrease (40 after 60)");
    EXPECT_EQ(mesh({{"mixing_mode", "gradient"}, {"mixing_gradient_stops", "0=1:0; 50"}}),
              "setting 'mixing_gradient_stops': stop '50' is not height=ratios (e.g. 50=0.5:0.5)");
    EXPECT_EQ(mesh({{"mixing_mode", "gradient"}, {"mixing_gradient_unit", "inch"}}),
              "setting 'mixing_gradient_unit': unknown unit 'inch' (percent or mm)");
    EXPECT_EQ(errorOf([] {
                  parseChamberVolumeMm3(scope({{"mixing_chamber_volume", "-2"}}));
              }),
              "setting 'mixing_chamber_volume': -2 mm³ is negative");
}

TEST(MixingSettings, SingleModeChecksNothingElse) {
    // A printer profile may carry mixing values that single mode never uses.
    EXPECT_EQ(errorOf([] {
                  parseMixingOutput(scope({{"mixing_dialect", "bambu"}, {"mixing_channels", "9"}}));
              }),
              "");
}

TEST(MixingSettings, RatiosAndStops) {
    const MixVector r = parseMixRatio("mixing_ratio", " 0.25 : 0.75 ", 2);
    EXPECT_EQ(r.channels, 2);
    EXPECT_EQ(r[0], 0.25);
    EXPECT_EQ(r[1], 0.75);
    const MixVector partial = parseMixRatio("mixing_ratio", "0:1", 4);  // channels 2 and 3 get 0
    EXPECT_EQ(partial, MixVector::only(1, 4));
    const auto stops = parseGradientStops("mixing_gradient_stops", "0=1:0:0; 50=0:1:0;100=0:0.5:0.5;", 3);
    ASSERT_EQ(stops.size(), 3u);
    EXPECT_EQ(stops[1].height, 50.0);
    EXPECT_EQ(stops[1].mix, MixVector::only(1, 3));
    EXPECT_EQ(stops[2].mix[2], 0.5);
}

TEST(MixingSettings, StopsReplaceStartAndEnd) {
    const Settings s = scope({{"mixing_mode", "gradient"},
                              {"mixing_dialect", "rrf_colon"},
                              {"mixing_channels", "3"},
                              {"mixing_gradient_unit", "mm"},
                              {"mixing_gradient_stops", "1=1:0:0; 5=0:0:1"}});
    const MeshMixing m = parseMeshMixing(s, parseMixingOutput(s));
    EXPECT_EQ(m.unit, HeightUnit::Millimetres);
    ASSERT_EQ(m.stops.size(), 2u);
    EXPECT_EQ(m.stops[1].mix, MixVector::only(2, 3));
}

TEST(MixingSettings, ChannelColours) {
    const auto colors = parseChannelColors(scope({{"mixing_channel_colors", "#102030, #A0B0C0"}}), 3);
    ASSERT_EQ(colors.size(), 3u);
    EXPECT_EQ(colors[0], (Rgb{0x10, 0x20, 0x30}));
    EXPECT_EQ(colors[1], (Rgb{0xa0, 0xb0, 0xc0}));
    EXPECT_EQ(colors[2], (Rgb{0x00, 0xa3, 0xe0}));  // the default third colour
    EXPECT_EQ(errorOf([] {
                  parseChannelColors(scope({{"mixing_channel_colors", "red"}}), 1);
              }),
              "setting 'mixing_channel_colors': 'red' is not a colour like #ff8800");
}

TEST(MixingSettingAliases, SeedNamesBecomeCanonicalKeys) {
    const SettingValues out = withCanonicalKeys(
        SettingValues{{"colorA", "20"}, {"colorMixing", "2"}, {"colorB", "80"}, {"layer_height", "0.2"}});
    EXPECT_EQ(out, (SettingValues{{"mixing_mode", "gradient"},
                                  {"mixing_gradient_start", "20"},
                                  {"mixing_gradient_end", "80"},
                                  {"mixing_gradient_unit", "percent"},
                                  {"layer_height", "0.2"}}));
    EXPECT_EQ(withCanonicalKeys(SettingValues{{"colorMode", "0"}}).at("mixing_mode"), "single");
    EXPECT_EQ(withCanonicalKeys(SettingValues{{"colorMode", "1"}}).at("mixing_mode"), "dual");
    EXPECT_EQ(withCanonicalKeys(SettingValues{{"colorMode", "gradient"}}).at("mixing_mode"), "gradient");
    // An explicit unit stays; values without aliases are untouched.
    EXPECT_EQ(withCanonicalKeys(SettingValues{{"colorA", "2"}, {"mixing_gradient_unit", "mm"}})
                  .at("mixing_gradient_unit"),
              "mm");
    EXPECT_EQ(withCanonicalKeys(SettingValues{{"speed_print", "60"}}),
              (SettingValues{{"speed_print", "60"}}));
    // Extruder values are translated as well.
    UserSettings user;
    user.extruders[1] = {{"colorB", "70"}};
    EXPECT_EQ(withCanonicalKeys(user).extruders.at(1).at("mixing_gradient_end"), "70");
}

TEST(MixingSettingAliases, ConflictsAndBadModesAreErrors) {
    EXPECT_EQ(
        errorOf([] {
            withCanonicalKeys(SettingValues{{"colorMode", "5"}});
        }),
        "setting 'colorMode' (alias of mixing_mode): value '5' is not 0, 1, 2, single, dual or gradient");
    EXPECT_EQ(errorOf([] {
                  withCanonicalKeys(SettingValues{{"colorA", "20"}, {"mixing_gradient_start", "30"}});
              }),
              "setting 'colorA' (alias of mixing_gradient_start) is '20' but mixing_gradient_start is '30'");
    EXPECT_EQ(errorOf([] {
                  withCanonicalKeys(SettingValues{{"colorA", "20"}, {"mixing_gradient_start", "20"}});
              }),
              "");
}

TEST(MixingSettings, RaftRatioDefaultsToFilamentA) {
    const MixingOutput out = parseMixingOutput(scope({{"mixing_mode", "gradient"}}));
    EXPECT_EQ(parseRaftMix(scope({}), out), MixVector::only(0, 2));
    EXPECT_EQ(parseRaftMix(scope({{"mixing_raft_ratio", "0.3:0.7"}}), out)[1], 0.7);
    EXPECT_EQ(errorOf([&] {
                  parseRaftMix(scope({{"mixing_raft_ratio", "0.3:0.3"}}), out);
              }),
              "setting 'mixing_raft_ratio': ratios '0.3:0.3' add up to 0.6, not 1");
}

}  // namespace
}  // namespace mixengine
