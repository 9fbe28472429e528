#pragma once
// Mixing-chamber delay compensation. The chamber holds `chamber_mm3` of material between the
// point where the filaments meet and the nozzle tip, so material mixed now leaves the nozzle only
// after that much more has been extruded (plug flow). To make the colour leaving the nozzle match
// the target at every place, the mix schedule is shifted earlier by the chamber volume along the
// cumulative extruded volume: extrusion i commands the target of the material that will be
// extruded when its own material reaches the tip — the target at cumulative volume
// (start of i + half its volume + chamber). Past the end of the print the last target holds.
#include <vector>

namespace mixengine {

/// `target[i]`: index of the mix wanted in extrusion i (print order); `volume_mm3[i]` its volume.
/// Returns the index of the mix to command for each extrusion. chamber_mm3 = 0 returns `target`.
std::vector<int> delayCompensated(const std::vector<int>& target, const std::vector<double>& volume_mm3,
                                  double chamber_mm3);

}  // namespace mixengine
