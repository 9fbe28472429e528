#pragma once
// The fan for skin printed above support (support_fan_enable, support_supported_skin_fan_speed), as
// CuraEngine 4.13: on layer n > 0 of a mesh with support_fan_enable (and support_enable on the group),
// each skin part that is not a bridge is looked at against the support top_gap + 1 layers below
// (top_gap = ceil(support_top_distance / layer_height)): against that layer's roof when it has one,
// else against its support body; a part that overlaps it prints with the fan at
// support_supported_skin_fan_speed. A skin part here is an island of the layer's skin lines grown by
// half their width (the lines of one part touch); its roofing lines belong to the part but keep the
// layer's fan, as CuraEngine prints roofing without this fan.
#include <vector>

#include "settings/Settings.h"
#include "toolpaths/MeshToolpaths.h"
#include "toolpaths/support/SupportAreas.h"

namespace mixengine {

/// Sets ExtrusionPath::fan_ratio of the supported skin of `layers` (one mesh's, index = layer; the
/// mesh's settings `mesh`, the group's `global`) from the support `support` (index = layer).
void markSupportedSkinFan(const Settings& global, const Settings& mesh,
                          const std::vector<SupportLayerAreas>& support, std::vector<MeshLayerGroups>& layers,
                          int threads);

}  // namespace mixengine
