#pragma once
// Line width, speed, flow and extruder of one feature on one layer, from Cura's keys:
//   width    — the feature's *_line_width, × initial_layer_line_width_factor on layer 0;
//   speed    — the feature's speed_*; layer 0 prints at speed_print_layer_0 and layers
//              1 … speed_slowdown_layers-1 ramp linearly from it (CuraEngine's smoothing):
//              v = v0 + (v − v0) · layer / speed_slowdown_layers; layers below the model
//              (negative: raft filler layers) print at the feature's own speed, as CuraEngine;
//   flow     — the feature's *_material_flow, × material_flow_layer_0 on layer 0;
//   extruder — the feature's *_extruder_nr; −1 (or none given) means the mesh's extruder_nr.
#include <optional>
#include <vector>

#include "geometry/Point.h"
#include "settings/Settings.h"
#include "toolpaths/core/ExtrusionPath.h"

namespace mixengine {

struct FeatureStyle {
    coord_um width_um = 400;
    double speed_mm_s = 60;
    double flow = 1.0;
    int extruder = 0;
};

struct FeatureKeys {
    Key<SettingUnit::Millimetres> width;
    Key<SettingUnit::MmPerS> speed;
    Key<SettingUnit::Percent> flow;
    std::optional<Key<SettingUnit::Extruder>> extruder;  ///< none: the scope's own extruder
};

/// The mesh's (or scope's) own extruder: extruder_nr, 0 when absent.
int ownExtruder(const Settings& s);

/// `key` on `layer` as CuraEngine 4.13 ramps it over the first layers: `first_key` (e.g.
/// speed_travel_layer_0) on layer 0, then linearly towards `key` over speed_slowdown_layers (reached on
/// that layer); below layer 0 (raft, filler layers), from that layer on (with speed_slowdown_layers 0:
/// layer 0 too) and without `first_key`, `key` itself.
/// The ramp of slowdownValue between a first-layer value and a value.
double slowdownBlend(const Settings& s, double value, double first, int layer);

template <SettingUnit U>
double slowdownValue(const Settings& s, Key<U> key, Key<U> first_key, int layer) {
    return slowdownBlend(s, s.number(key), s.number(first_key), layer);
}

/// Speed of `speed_key` on `layer` with the first-layer speed and the slow-down ramp (none below
/// layer 0).
double layerSpeed(const Settings& s, Key<SettingUnit::MmPerS> speed_key, int layer);

FeatureStyle featureStyle(const Settings& s, const FeatureKeys& keys, int layer);

/// A path of `feature` through `points` with the style's width, speed, flow and extruder.
ExtrusionPath styledPath(const Path& points, bool closed, Feature feature, const FeatureStyle& style);

/// Appends every loop of `loops` with at least three points as a closed path of `feature` in `style`.
void appendStyledLoops(const Paths& loops, Feature feature, const FeatureStyle& style,
                       std::vector<ExtrusionPath>& out);

/// The styles of a mesh's own features on one layer.
struct MeshStyles {
    FeatureStyle wall_0, wall_x, skin, roofing, infill;
};

MeshStyles meshStyles(const Settings& s, int layer);

}  // namespace mixengine
