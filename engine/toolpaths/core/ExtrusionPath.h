#pragma once
// The output of toolpath generation: typed extrusion lines per layer, plain data.
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "geometry/Point.h"

namespace mixengine {

/// Feature types, named as Cura's ;TYPE: markers name them. Ironing, roofing, the three raft layers
/// and the draft shield are features of their own (own speeds, accelerations, jerks or mix) that
/// CuraEngine 4.13 marks with an existing type: ironing and roofing SKIN, raft base and surface
/// SUPPORT-INTERFACE, raft interface SUPPORT, draft shield SKIRT (printed with the skirt's style).
enum class Feature {
    WallOuter,
    WallInner,
    Skin,
    Fill,
    Support,
    SupportInterface,
    Skirt,
    PrimeTower,
    Ironing,
    RaftBase,
    RaftInterface,
    RaftSurface,
    DraftShield,
    SupportBottom,  ///< the support's floor: an interface with its own acceleration and jerk
    Roofing,        ///< the top-most skin (roofing_layer_count): skin with its own acceleration and jerk
};

std::string_view featureMarker(Feature feature);  ///< "WALL-OUTER", "FILL", ...

/// The feature CuraEngine files `feature` under (;TYPE:, time estimates, preview line types):
/// Ironing and Roofing → Skin, RaftBase/RaftSurface/SupportBottom → SupportInterface, RaftInterface →
/// Support, else itself.
Feature markedFeature(Feature feature);

/// How a wall prints where it crosses air (bridge_wall_*; toolpaths/walls/BridgeWalls.h).
struct BridgeWallStyle {
    double speed_mm_s = 0;   ///< bridge_wall_speed
    double flow = 1.0;       ///< bridge_wall_material_flow
    double fan_ratio = 1.0;  ///< bridge_fan_speed
    double coast = 1.0;      ///< bridge_wall_coast (fraction)
};

/// ExtrusionPath::air_edges values: the edge's kind in the low bits, kContinuesEdge when it is
/// the continuation of the same wall edge as the edge before it (split where the edge meets air).
enum AirEdge : std::uint8_t { kSupported = 0, kShortAir = 1, kBridged = 2, kContinuesEdge = 4 };

struct ExtrusionPath {
    Path points;            ///< microns
    bool closed = false;    ///< a loop: the printer returns to points.front()
    coord_um width_um = 0;  ///< line width
    Feature feature = Feature::Fill;
    double speed_mm_s = 0;
    double flow = 1.0;  ///< multiplier on the nominal width × thickness volume
    int extruder = 0;   ///< extruder train that prints it
    /// Print from points.front(): a loop whose seam is chosen (z_seam_type), or an open line that runs
    /// across the monotonic direction (monotonic ironing, toolpaths/surface/Ironing.h).
    bool fixed_start = false;
    /// 0, or the number of a sequence: the paths of a group with the same non-zero sequence are
    /// printed one after the other in list order once the first of them is reached (a monotonic
    /// skin); the planner still picks which end of each line to start from.
    std::uint32_t sequence = 0;
    /// Skin (toolpaths/skin/SkinPaths.h): the skin part the path fills, numbered from 1 within the
    /// layer (0: none), and its stage there (1 the part's loops, 2 roofing, 3 skin fill, 4 the lines
    /// filling a concentric fill's gaps). The planner prints a skin part's paths together, stage by
    /// stage, as CuraEngine 4.13 prints each skin part.
    std::uint32_t skin_part = 0;
    std::uint8_t skin_stage = 0;
    /// A skin or roofing fill of lines (not monotonic, top_bottom_pattern lines or zigzag): the two
    /// points of its area the planner starts looking for its first line from — the one nearer to
    /// the head — as CuraEngine 4.13 starts such a fill away from the seam
    /// (FffGcodeWriter::getSeamAvoidingLocation). Set on every line of the fill, or on none.
    std::optional<std::array<Point2, 2>> seam_avoiding_starts;
    /// Printed in the order of its group, not nearest first (monotonic ironing); only the end to
    /// start from is chosen. Set on every path of the group or on none.
    bool keep_order = false;
    /// Spiralize (toolpaths/surface/Spiralize.h): the nozzle rises from the layer's z at points.front() by
    /// one layer thickness over the whole path, in proportion to the length printed, but stops
    /// rising for the last `spiral_flat_tail` points (CuraEngine's tapering round on the top layer).
    bool spiral = false;
    std::size_t spiral_flat_tail = 0;
    /// Empty, or one flow per point: flows[k] is the flow of the line that ends at points[k]
    /// (flows[0]: a loop's closing line; not used on an open path); 0 moves without extruding.
    /// Replaces `flow` when given.
    std::vector<double> flows;

    /// Printed with bridge settings (toolpaths/skin/BridgeSkin.h): ;BRIDGE after its ;TYPE:, and the
    /// fan at `fan_ratio` (0..1; −1: the layer's fan) while it prints.
    bool bridge = false;
    double fan_ratio = -1;
    /// A line filling a gap between a part's walls or between its walls and its skin or infill,
    /// which the planner may merge with its neighbours (mergeGapLines, planning/Cooling.h).
    bool mergeable = false;
    /// A wall loop crossing air: per edge points[k] → points[k+1] its AirEdge bits, and how it
    /// prints bridged; empty / none for everything else.
    std::vector<std::uint8_t> air_edges;
    std::optional<BridgeWallStyle> bridge_wall;
    /// An overhanging wall loop (toolpaths/walls/OverhangWalls.h): empty, or one flag per point, non-zero
    /// where the point overhangs. A line with an overhanging end prints at speed × overhang_speed_factor,
    /// and the loop starts at its first point from the chosen start that does not overhang.
    std::vector<std::uint8_t> overhanging;
    double overhang_speed_factor = 1.0;
};

}  // namespace mixengine
