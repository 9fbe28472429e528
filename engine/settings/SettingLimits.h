#pragma once
// Limits on resolved setting values beyond which a slice has no physical meaning and its size (lines
// per layer) grows without bound: Cura allows a line width down to 0.001 mm (minimum_value), which
// makes a 10 mm cube take minutes and a larger model hours. Checked before slicing.
//
// checkLineWidths(): every `*line_width` value of the scope, and the first layer's width (times
// initial_layer_line_width_factor), must be at least kMinLineWidthMm. Otherwise throws InputError
// "setting '<key>': ..." naming the key at fault; when that key's value was computed rather than
// given, the message also names the settings the user gave (`given`), one of which caused it.
#include <string>
#include <vector>

#include "settings/Settings.h"

namespace mixengine {

constexpr double kMinLineWidthMm = 0.01;  ///< 1/40 of a 0.4 mm nozzle's line

void checkLineWidths(const Settings& settings, const std::vector<std::string>& given);

}  // namespace mixengine
