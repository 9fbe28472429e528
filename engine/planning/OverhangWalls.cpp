#include "planning/OverhangWalls.h"

namespace mixengine {

bool overhangsAt(const ExtrusionPath& path, std::size_t k) {
    return path.overhanging.size() == path.points.size() && k < path.overhanging.size() &&
           path.overhanging[k] != 0;
}

std::size_t firstNonOverhanging(const ExtrusionPath& path, std::size_t start) {
    const std::size_t n = path.points.size();
    if (path.overhanging.size() != n)
        return start;
    for (std::size_t t = 0; t < n; ++t) {
        if (!overhangsAt(path, (start + t) % n))
            return (start + t) % n;
    }
    return start;
}

double overhangSpeedFactor(const ExtrusionPath& path, std::size_t from, std::size_t to) {
    return overhangsAt(path, from) || overhangsAt(path, to) ? path.overhang_speed_factor : 1.0;
}

}  // namespace mixengine
