#include "geometry/SideBySide.h"

#include <algorithm>
#include <limits>

namespace mixengine {
namespace {

struct XRange {
    coord_um left_um, right_um;
    std::size_t index;
};

XRange rangeOf(const Path& loop, std::size_t index) {
    XRange range{std::numeric_limits<coord_um>::max(), std::numeric_limits<coord_um>::min(), index};
    for (const Point2& p : loop) {
        range.left_um = std::min(range.left_um, p.X);
        range.right_um = std::max(range.right_um, p.X);
    }
    return range;
}

}  // namespace

std::vector<std::vector<std::size_t>> sideBySideGroups(const Paths& a, const Paths& b, coord_um reach_um) {
    std::vector<XRange> ranges;
    ranges.reserve(a.size() + b.size());
    for (std::size_t k = 0; k < a.size() + b.size(); ++k) {
        const Path& loop = k < a.size() ? a[k] : b[k - a.size()];
        if (!loop.empty())
            ranges.push_back(rangeOf(loop, k));
    }
    std::sort(ranges.begin(), ranges.end(), [](const XRange& x, const XRange& y) {
        return x.left_um != y.left_um ? x.left_um < y.left_um : x.index < y.index;
    });
    std::vector<std::vector<std::size_t>> groups;
    coord_um reached = std::numeric_limits<coord_um>::min();
    for (const XRange& range : ranges) {
        if (groups.empty() || range.left_um - reach_um > reached)
            groups.emplace_back();
        groups.back().push_back(range.index);
        reached = std::max(reached, range.right_um + reach_um);
    }
    if (groups.size() <= 1)
        return {};
    for (std::vector<std::size_t>& group : groups)
        std::sort(group.begin(), group.end());
    return groups;
}

}  // namespace mixengine
