// The file header (gcode/Header.h): exact lines per flavour and the flavour mapping.
#include "gcode/Header.h"

#include <gtest/gtest.h>

namespace mixengine {
namespace {

PrintSummary summary(Flavor flavor) {
    PrintSummary s;
    s.flavor = flavor;
    s.print_time_s = 5626.2;
    s.filament_per_extruder = {732.079};
    s.layer_height_mm = 0.1;
    s.min = {100'000, 90'500, 300};
    s.max = {123'456, 110'000, 10'000};
    s.engine_version = "0.1.0";
    return s;
}

constexpr const char* kBounds =
    ";MINX:100\n;MINY:90.5\n;MINZ:0.3\n;MAXX:123.456\n;MAXY:110\n;MAXZ:10\n\n;Generated with MixEngine "
    "0.1.0\n";

TEST(Header, Marlin) {
    EXPECT_EQ(makeHeader(summary(Flavor::Marlin)), std::string(";FLAVOR:Marlin\n"
                                                               ";TIME:5626\n"
                                                               ";Filament used: 0.732079m\n"
                                                               ";Layer height: 0.1\n") +
                                                       kBounds);
}

TEST(Header, RepRapWithTwoExtruders) {
    PrintSummary s = summary(Flavor::RepRap);
    s.filament_per_extruder = {732.079, 506.119};
    s.layer_height_mm = 0.15;
    EXPECT_EQ(makeHeader(s), std::string(";FLAVOR:RepRap\n"
                                         ";TIME:5626\n"
                                         ";Filament used: 0.732079m, 0.506119m\n"
                                         ";Layer height: 0.15\n") +
                                 kBounds);
}

TEST(Header, VolumetricReportsCubicMillimetres) {
    PrintSummary s = summary(Flavor::MarlinVolumetric);
    s.filament_per_extruder = {16200.0, 4670.12};
    EXPECT_EQ(makeHeader(s), std::string(";FLAVOR:Marlin(Volumetric)\n"
                                         ";TIME:5626\n"
                                         ";Filament used: 16200mm3, 4670.12mm3\n"
                                         ";Layer height: 0.1\n") +
                                 kBounds);
}

TEST(Header, NoFilamentIsZeroMetres) {
    PrintSummary s = summary(Flavor::Marlin);
    s.filament_per_extruder.clear();
    EXPECT_NE(makeHeader(s).find("\n;Filament used: 0m\n"), std::string::npos) << makeHeader(s);
}

// Any other machine_gcode_flavor text (gcode/Flavor.h Unknown) gets Marlin's header.
TEST(Header, UnknownFlavorWritesMarlinsHeader) {
    EXPECT_EQ(makeHeader(summary(Flavor::Unknown)), makeHeader(summary(Flavor::Marlin)));
}

// CuraEngine 4.13 writes `static_cast<int>(print_time)` (GCodeExport::getFileHeader), i.e. truncates.
// BUG (engine/gcode/Header.cpp, makeHeader: `std::lround(summary.print_time_s)`) rounds 5626.7 up.
TEST(Header, TimeIsTruncatedLikeCuraEngine) {
    PrintSummary s = summary(Flavor::Marlin);
    s.print_time_s = 5626.7;
    EXPECT_NE(makeHeader(s).find("\n;TIME:5626\n"), std::string::npos) << makeHeader(s);
}

// CuraEngine 4.13 streams the filament with the default 6 significant digits
// (`filament_used / (1000 * filament_area) << "m"`): 2553.456 mm → "2.55346m", 123456.78 mm³ →
// "123457mm3". BUG (engine/gcode/Header.cpp, filamentList: formatDecimal(value / 1000, 6) and
// formatDecimal(value, 2)) writes "2.553456m" and "123456.78mm3".
TEST(Header, FilamentHasSixSignificantDigitsLikeCuraEngine) {
    PrintSummary s = summary(Flavor::Marlin);
    s.filament_per_extruder = {2553.456};
    EXPECT_NE(makeHeader(s).find("\n;Filament used: 2.55346m\n"), std::string::npos) << makeHeader(s);
    s.flavor = Flavor::MarlinVolumetric;
    s.filament_per_extruder = {123456.78};
    EXPECT_NE(makeHeader(s).find("\n;Filament used: 123457mm3\n"), std::string::npos) << makeHeader(s);
}

// /usr/bin/CuraEngine (4.13) with machine_gcode_flavor=MACH3 / Repetier / BFB / Makerbot writes
// ";FLAVOR:Mach3" / "Repetier" / "BFB" / "Makerbot" and no ";Filament used:" / ";Layer height:" lines
// (those are written for Marlin, RepRap and Marlin(Volumetric) only).
TEST(Header, OtherFlavoursKeepTheirNameLikeCuraEngine) {
    const std::string header = makeHeader(summary(Flavor::Mach3));
    EXPECT_EQ(header.rfind(";FLAVOR:Mach3\n;TIME:5626\n;MINX:", 0), 0U) << header;
    EXPECT_EQ(makeHeader(summary(Flavor::Repetier)).rfind(";FLAVOR:Repetier\n;TIME:5626\n;MINX:", 0), 0U);
    EXPECT_EQ(makeHeader(summary(Flavor::Makerbot)).rfind(";FLAVOR:Makerbot\n;TIME:5626\n;MINX:", 0), 0U);
    EXPECT_EQ(makeHeader(summary(Flavor::Bfb)).rfind(";FLAVOR:BFB\n;TIME:5626\n;MINX:", 0), 0U);
}

TEST(Header, GriffinBlockWithRealValues) {
    PrintSummary s = summary(Flavor::Griffin);
    s.machine_name = "Ultimaker S5";
    s.build_plate_temperature_c = 60;
    ExtruderHeader e0;
    e0.initial_temperature_c = 215;
    e0.nozzle_diameter_mm = 0.4;
    e0.nozzle_name = "AA 0.4";
    e0.material_guid = "506c9f0d-e3aa-4bd4-b2d2-23e2425b1aa9";
    e0.volume_used_mm3 = 1234.6;
    ExtruderHeader e1;
    e1.used = false;
    s.extruders = {e0, e1};
    EXPECT_EQ(makeHeader(s),
              ";START_OF_HEADER\n;HEADER_VERSION:0.1\n;FLAVOR:Griffin\n;GENERATOR.NAME:MixEngine\n"
              ";GENERATOR.VERSION:0.1.0\n;TARGET_MACHINE.NAME:Ultimaker S5\n"
              ";EXTRUDER_TRAIN.0.INITIAL_TEMPERATURE:215\n;EXTRUDER_TRAIN.0.MATERIAL.VOLUME_USED:1235\n"
              ";EXTRUDER_TRAIN.0.MATERIAL.GUID:506c9f0d-e3aa-4bd4-b2d2-23e2425b1aa9\n"
              ";EXTRUDER_TRAIN.0.NOZZLE.DIAMETER:0.4\n;EXTRUDER_TRAIN.0.NOZZLE.NAME:AA 0.4\n"
              ";BUILD_PLATE.TYPE:glass\n;BUILD_PLATE.INITIAL_TEMPERATURE:60\n;PRINT.TIME:5626\n"
              ";PRINT.GROUPS:1\n;PRINT.SIZE.MIN.X:100\n;PRINT.SIZE.MIN.Y:90.5\n;PRINT.SIZE.MIN.Z:0.3\n"
              ";PRINT.SIZE.MAX.X:123.456\n;PRINT.SIZE.MAX.Y:110\n;PRINT.SIZE.MAX.Z:10\n;END_OF_HEADER\n"
              "\n;Generated with MixEngine 0.1.0\n");
}

TEST(Header, UltiGCodeMaterialVolumes) {
    PrintSummary s = summary(Flavor::UltiGCode);
    ExtruderHeader e0;
    e0.volume_used_mm3 = 6666.4;
    e0.nozzle_diameter_mm = 0.4;
    s.extruders = {e0};
    EXPECT_EQ(
        makeHeader(s),
        std::string(";FLAVOR:UltiGCode\n;TIME:5626\n;MATERIAL:6666\n;MATERIAL2:0\n;NOZZLE_DIAMETER:0.4\n") +
            kBounds);
}

}  // namespace
}  // namespace mixengine
