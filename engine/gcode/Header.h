#pragma once
// The file header Cura's tools read (;FLAVOR:, ;TIME:, ;Filament used:, ;Layer height:, bounds),
// written with the real values once the print is known.
#include <string>
#include <vector>

#include "geometry/Point.h"

namespace mixengine {

enum class Flavor { Marlin, MarlinVolumetric, RepRap, Griffin, UltiGCode, Other };

/// From machine_gcode_flavor ("RepRap (Marlin/Sprinter)", ...); unknown text → Other.
Flavor flavorFromSetting(const std::string& text);
std::string flavorName(Flavor flavor);  ///< ";FLAVOR:" text: "Marlin", "RepRap", ...

struct PrintSummary {
    Flavor flavor = Flavor::Marlin;
    double print_time_s = 0;
    std::vector<double> filament_per_extruder;  ///< mm of filament (mm³ when volumetric)
    double layer_height_mm = 0.1;
    Point3 min{}, max{};  ///< bounds of the extruded moves, microns
    std::string engine_version;
};

std::string makeHeader(const PrintSummary& summary);

}  // namespace mixengine
