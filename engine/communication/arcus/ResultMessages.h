#pragma once
// The messages the engine sends back to Cura (shared/reference/cura-integration.md §5), built
// from the pipeline's plain results. Units on the wire: material amounts in mm³ (one entry per
// extruder train, in train order, since Cura reads them by position), times in seconds.
#include <memory>
#include <string>
#include <vector>

#include <Arcus/Types.h>

#include "gcode/Header.h"

namespace mixengine {

Arcus::MessagePtr progressMessage(double amount);
Arcus::MessagePtr gcodeLayerMessage(const std::string& gcode);
Arcus::MessagePtr gcodePrefixMessage(const std::string& header);
Arcus::MessagePtr slicingFinishedMessage();

/// One material estimate per extruder train: summary.extruders[i].volume_used_mm3 (filled by the
/// pipeline for every train, used or not). The print time is reported as one total (Cura sums the
/// per-feature fields).
Arcus::MessagePtr estimatesMessage(const PrintSummary& summary);

}  // namespace mixengine
