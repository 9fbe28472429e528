#pragma once
// Shapes and settings shared by the toolpath tests.
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "geometry/Point.h"
#include "settings/DefinitionSet.h"
#include "settings/Resolver.h"
#include "slicing/LayerHeights.h"
#include "slicing/Slicer.h"
#include "toolpaths/GroupToolpaths.h"
#include "toolpaths/core/ExtrusionPath.h"

namespace mixengine::test {

/// An axis-aligned rectangle, counter-clockwise.
inline Path rect(coord_um x0, coord_um y0, coord_um x1, coord_um y1) {
    return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

inline Path square(coord_um x0, coord_um y0, coord_um size) {
    return rect(x0, y0, x0 + size, y0 + size);
}

/// Length of an open polyline in µm.
inline double polylineLength(const Path& p) {
    double total = 0;
    for (std::size_t i = 1; i < p.size(); ++i)
        total += std::hypot(double(p[i].X - p[i - 1].X), double(p[i].Y - p[i - 1].Y));
    return total;
}

inline double pathLength(const ExtrusionPath& p) {
    double total = 0;
    for (std::size_t i = 1; i < p.points.size(); ++i)
        total +=
            std::hypot(double(p.points[i].X - p.points[i - 1].X), double(p.points[i].Y - p.points[i - 1].Y));
    if (p.closed && p.points.size() > 2)
        total += std::hypot(double(p.points.front().X - p.points.back().X),
                            double(p.points.front().Y - p.points.back().Y));
    return total;
}

inline double totalLength(const std::vector<ExtrusionPath>& paths) {
    double total = 0;
    for (const ExtrusionPath& p : paths)
        total += pathLength(p);
    return total;
}

/// Cura's fdmprinter (with MixEngine's settings) with all formulas evaluated, plus `user` values (global) and
/// per-extruder ones.
inline ResolvedMachine fdmMachine(const SettingValues& user = {},
                                  const std::map<int, SettingValues>& trains = {}) {
    // as the engine: MixEngine's own definitions (settings/mixengine/) with Cura's
    static const DefinitionSet defs = loadDefinitionSet("fdmprinter", defaultSearchPath(nullptr));
    UserSettings values;
    values.global = user;
    values.extruders = trains;
    return resolveMachine(defs, values);
}

/// Layer heights and sliced layers of a stack of prisms: layers [from, to) have `outlines`.
struct Stack {
    std::vector<LayerZ> heights;
    std::vector<SlicedLayer> layers;
};

inline Stack prismStack(int layer_count, coord_um h0 = 300, coord_um h = 100) {
    Stack s;
    s.heights = computeLayerHeights(h0 + h * (layer_count - 1), h0, h);
    s.layers.resize(s.heights.size());
    for (std::size_t i = 0; i < s.layers.size(); ++i) {
        s.layers[i].print_z = s.heights[i].print_z;
        s.layers[i].slice_z = s.heights[i].slice_z;
    }
    return s;
}

inline void fill(Stack& s, int from, int to, const Paths& outlines) {
    for (int i = from; i < to && i < static_cast<int>(s.layers.size()); ++i) {
        Paths& o = s.layers[static_cast<std::size_t>(i)].outlines;
        o.insert(o.end(), outlines.begin(), outlines.end());
    }
}

/// The group toolpaths of one mesh, `stack`, printed with the machine's global settings (on 2 threads).
inline GroupToolpaths oneMeshToolpaths(const ResolvedMachine& machine, const Stack& stack, const char* name) {
    ToolpathInput in{&machine.global,
                     &machine.extruders,
                     stack.heights,
                     {{&machine.global, name, &stack.layers, std::nullopt, {}}},
                     {}};
    return generateGroupToolpaths(in, 2);
}

/// A 10 mm square prism ("cube") of `layers` layers at (100, 100) mm on fdmMachine(`user`), with
/// its group toolpaths. Built in place and never copied or moved: the toolpaths point into the
/// machine's settings and the stack.
struct CubePrint {
    explicit CubePrint(const SettingValues& user, int layers = 20)
        : machine(fdmMachine(user)), stack(prismStack(layers)) {
        fill(stack, 0, layers, {square(100'000, 100'000, 10'000)});
        toolpaths = oneMeshToolpaths(machine, stack, "cube");
    }
    CubePrint(const CubePrint&) = delete;
    CubePrint& operator=(const CubePrint&) = delete;

    ResolvedMachine machine;
    Stack stack;
    GroupToolpaths toolpaths;
};

}  // namespace mixengine::test
