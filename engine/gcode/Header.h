#pragma once
// The file header Cura's tools read (;FLAVOR:, ;TIME:, ;Filament used:, ;Layer height:, bounds),
// written with the real values once the print is known.
#include <string>
#include <vector>

#include "gcode/Flavor.h"
#include "gcode/TimeEstimate.h"
#include "geometry/Point.h"

namespace mixengine {

/// What Griffin and UltiGCode headers tell of each extruder train.
struct ExtruderHeader {
    double initial_temperature_c = 0;
    double nozzle_diameter_mm = 0.4;
    std::string nozzle_name = "unknown";
    std::string material_guid;  ///< empty: not written
    double volume_used_mm3 = 0;
    bool used = true;
};

struct PrintSummary {
    Flavor flavor = Flavor::Marlin;
    double print_time_s = 0;
    FeatureSeconds time_by_feature_s{};         ///< print_time_s split by feature (CuraEngine's buckets)
    std::vector<double> filament_per_extruder;  ///< mm of filament (mm³ when volumetric)
    double layer_height_mm = 0.1;
    Point3 min{}, max{};  ///< bounds of the extruded moves, microns
    std::string engine_version;
    // Griffin / UltiGCode only:
    std::string machine_name = "Unknown";
    std::vector<ExtruderHeader> extruders;
    std::string build_plate_type = "glass";
    double build_plate_temperature_c = 0;
    int print_groups = 1;
    /// Comment lines (without ';') after the usual header: the mixing report (mixing/MixingReport.h)
    std::vector<std::string> extra_lines;
};

/// The header for summary.flavor, laid out as its FlavorTraits::header says (gcode/Flavor.h):
/// Griffin's ;START_OF_HEADER block, UltiGCode's ;MATERIAL: lines, or the Marlin/RepRap lines
/// (;FLAVOR:, ;TIME:, ;Filament used:, ;Layer height:, bounds); BFB and Mach3, Repetier and
/// Makerbot, as CuraEngine, only ;FLAVOR:, ;TIME: and the bounds.
std::string makeHeader(const PrintSummary& summary);

}  // namespace mixengine
