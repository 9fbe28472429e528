#pragma once
// Start and end G-code: the temperature lines Cura prepends (material_bed_temp_prepend,
// material_print_temp_prepend and their *_wait flags), the machine's start/end code as the
// settings hold it (tokens were expanded by the frontend, or by settings/FrontendValues for the
// command line), and the extrusion mode lines.
#include <string>

#include "settings/Settings.h"

namespace mixengine {

std::string startCode(const Settings& global, const Settings& extruder0, bool relative_extrusion);
std::string endCode(const Settings& global, bool relative_extrusion);

}  // namespace mixengine
