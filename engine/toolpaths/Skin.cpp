#include "toolpaths/Skin.h"

#include "common/ParallelFor.h"

namespace mixengine {

namespace {

Paths clip(const Paths& a, const Paths& b, ClipperLib::ClipType operation) {
    ClipperLib::Clipper clipper;
    clipper.AddPaths(a, ClipperLib::ptSubject, true);
    clipper.AddPaths(b, ClipperLib::ptClip, true);
    Paths result;
    clipper.Execute(operation, result, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    return result;
}

}  // namespace

Paths intersectAll(const Paths& a, const Paths& b) {
    return clip(a, b, ClipperLib::ctIntersection);
}

Paths differenceOf(const Paths& a, const Paths& b) {
    return clip(a, b, ClipperLib::ctDifference);
}

std::vector<Paths> computeSkinAreas(const std::vector<Paths>& areas, int top_layers, int bottom_layers,
                                    int threads) {
    const int count = static_cast<int>(areas.size());
    std::vector<Paths> skins(areas.size());
    parallelFor(areas.size(), threads, [&](std::size_t index) {
        const int i = static_cast<int>(index);
        if (areas[index].empty())
            return;
        // The region supported on both sides: covered by every layer in the window.
        Paths interior = areas[index];
        for (int d = 1; d <= top_layers && !interior.empty(); ++d) {
            interior =
                i + d < count ? intersectAll(interior, areas[static_cast<std::size_t>(i + d)]) : Paths{};
        }
        for (int d = 1; d <= bottom_layers && !interior.empty(); ++d) {
            interior = i - d >= 0 ? intersectAll(interior, areas[static_cast<std::size_t>(i - d)]) : Paths{};
        }
        skins[index] = differenceOf(areas[index], interior);
    });
    return skins;
}

}  // namespace mixengine
