#include "toolpaths/adhesion/Raft.h"

#include <string>

#include "geometry/PolygonOps.h"
#include "slicing/OutlineCleanup.h"
#include "toolpaths/core/FeatureStyle.h"
#include "toolpaths/infill/LineInfill.h"
#include "toolpaths/infill/ZigZag.h"
#include "toolpaths/support/Support.h"

namespace mixengine {
namespace {

/// CuraEngine's default simplification of the interface and surface areas (10 µm segments, 5 µm).
constexpr coord_um kFineResolutionUm = 10;
constexpr coord_um kFineDeviationUm = 5;

/// One raft layer's kind: its keys, feature and line direction.
/// The settings of one of the raft's three kinds of layer (raft_base_*, raft_interface_*, raft_surface_*).
struct RaftKeys {
    Key<SettingUnit::Millimetres> line_width, line_spacing, thickness;
    Key<SettingUnit::MmPerS> speed;
    Key<SettingUnit::Percent> fan_speed;
};

constexpr RaftKeys kBaseKeys{key::raft_base_line_width, key::raft_base_line_spacing, key::raft_base_thickness,
                             key::raft_base_speed, key::raft_base_fan_speed};
constexpr RaftKeys kInterfaceKeys{key::raft_interface_line_width, key::raft_interface_line_spacing,
                                  key::raft_interface_thickness, key::raft_interface_speed,
                                  key::raft_interface_fan_speed};
constexpr RaftKeys kSurfaceKeys{key::raft_surface_line_width, key::raft_surface_line_spacing,
                                key::raft_surface_thickness, key::raft_surface_speed,
                                key::raft_surface_fan_speed};

struct RaftLayerKind {
    RaftKeys keys;
    Feature feature = Feature::RaftBase;
    double angle_degrees = 0;
};

Paths simplified(const Paths& loops, coord_um resolution_um, coord_um deviation_um) {
    Paths out;
    for (const Path& loop : loops) {
        Path simple = simplifyLoop(loop, resolution_um, deviation_um);
        if (simple.size() >= 3)
            out.push_back(std::move(simple));
    }
    return out;
}

FeatureStyle raftStyle(const Settings& s, const RaftKeys& keys, int extruder) {
    FeatureStyle style;
    style.width_um = s.lengthMicrons(keys.line_width);
    style.speed_mm_s = s.velocityMmPerS(keys.speed);
    style.flow = 1.0;
    style.extruder = extruder;
    return style;
}

void appendLines(const Paths& lines, Feature feature, const FeatureStyle& style,
                 std::vector<ExtrusionPath>& out) {
    for (const Path& line : lines) {
        if (line.size() >= 2)
            out.push_back(styledPath(line, false, feature, style));
    }
}

/// The paths of one raft layer of `kind` over `outline`.
std::vector<ExtrusionPath> raftLayerPaths(const Paths& outline, const Settings& s, const RaftLayerKind& kind,
                                          int extruder) {
    const FeatureStyle style = raftStyle(s, kind.keys, extruder);
    const coord_um spacing = s.lengthMicrons(kind.keys.line_spacing);
    std::vector<ExtrusionPath> out;
    if (style.width_um <= 0 || spacing <= 0)
        return out;
    const Paths inside = offsetMiter(outline, -style.width_um / 2);
    if (kind.feature == Feature::RaftBase) {
        const Paths wall = simplified(inside, s.lengthMicrons(key::meshfix_maximum_resolution),
                                      s.lengthMicrons(key::meshfix_maximum_deviation));
        appendStyledLoops(wall, kind.feature, style, out);
        appendLines(lineSegments(wall, spacing, kind.angle_degrees, 0), kind.feature, style, out);
        return out;
    }
    const Paths area = simplified(inside, kFineResolutionUm, kFineDeviationUm);
    appendLines(zigzagLines(area, spacing, kind.angle_degrees, 0, ZigzagEnds::Open), kind.feature, style,
                out);
    return out;
}

std::vector<RaftLayerKind> layerKinds(int surface_layers) {
    std::vector<RaftLayerKind> kinds{
        {kBaseKeys, Feature::RaftBase, 0},
        {kInterfaceKeys, Feature::RaftInterface, surface_layers > 0 ? 45.0 : 90.0}};
    for (int k = 1; k <= surface_layers; ++k)
        kinds.push_back({kSurfaceKeys, Feature::RaftSurface, 90.0 * k});
    return kinds;
}

}  // namespace

Paths raftOutline(const Paths& first_layer, coord_um margin_um, coord_um smoothing_um) {
    const Paths grown = offsetPolygons(unionOf(first_layer), margin_um);
    if (smoothing_um <= 0)
        return grown;
    return offsetPolygons(offsetPolygons(grown, smoothing_um), -smoothing_um);
}

RaftToolpaths generateRaft(const RaftInput& in) {
    RaftToolpaths raft;
    const RaftLayout layout = raftLayout(*in.global, in.extruders);
    if (!layout.enabled || in.first_layer.empty())
        return raft;
    const Settings& s = trainSettings(*in.global, in.extruders, layout.extruder);
    raft.outline =
        raftOutline(in.first_layer, s.lengthMicrons(key::raft_margin), s.lengthMicrons(key::raft_smoothing));
    int index = -layout.extraLayerCount();
    coord_um z = 0;
    for (const RaftLayerKind& kind : layerKinds(layout.surface_layers)) {
        RaftLayer layer;
        layer.index = index++;
        layer.thickness_um = s.lengthMicrons(kind.keys.thickness);
        z += layer.thickness_um;
        layer.z_um = z;
        layer.fan_ratio = s.ratio(kind.keys.fan_speed);
        layer.paths = raftLayerPaths(raft.outline, s, kind, layout.extruder);
        raft.layers.push_back(std::move(layer));
    }
    return raft;
}

}  // namespace mixengine
