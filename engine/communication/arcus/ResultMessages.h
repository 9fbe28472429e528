#pragma once
// The messages the engine sends back to Cura (shared/reference/cura-integration.md §5), built
// from the pipeline's plain results. Units on the wire: material amounts in mm³ (one entry per
// extruder train, in train order, since Cura reads them by position), times in seconds.
#include <memory>
#include <string>
#include <vector>

#include <google/protobuf/message.h>

#include "gcode/Header.h"

namespace mixengine {

using MessagePtr = std::shared_ptr<google::protobuf::Message>;

MessagePtr progressMessage(double amount);
MessagePtr gcodeLayerMessage(const std::string& gcode);
MessagePtr gcodePrefixMessage(const std::string& header);
MessagePtr slicingFinishedMessage();

/// One material estimate per extruder train: summary.extruders[i].volume_used_mm3 (filled by the
/// pipeline for every train, used or not). The print time goes into the 12 time_* fields by feature,
/// as CuraEngine books it (summary.time_by_feature_s); Cura shows their sum as the total.
MessagePtr estimatesMessage(const PrintSummary& summary);

}  // namespace mixengine
