#include "slicing/SegmentStitcher.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "slicing/GapCloser.h"

namespace mixengine {
namespace {

double segmentLength(const FacetSegment& segment) {
    const double dx = static_cast<double>(segment.to.X - segment.from.X);
    const double dy = static_cast<double>(segment.to.Y - segment.from.Y);
    return std::sqrt(dx * dx + dy * dy);
}

std::size_t segmentOf(std::int32_t end_id) {
    return static_cast<std::size_t>(end_id) / 2;
}
bool isStartEnd(std::int32_t end_id) {
    return end_id % 2 == 0;
}

}  // namespace

std::int32_t SegmentStitcher::takeEndAt(const Point2& point, bool prefer_start) {
    std::int32_t fallback = PointMultimap::kNone;
    for (std::int32_t id = ends_.first(point); id != PointMultimap::kNone; id = ends_.nextAtSamePoint(id)) {
        if (used_[segmentOf(id)])
            continue;
        if (isStartEnd(id) == prefer_start) {
            fallback = id;
            break;
        }
        if (fallback == PointMultimap::kNone)
            fallback = id;
    }
    if (fallback != PointMultimap::kNone)
        used_[segmentOf(fallback)] = 1;
    return fallback;
}

bool SegmentStitcher::extendForward(StitchedPath& path, const std::vector<FacetSegment>& segments) {
    while (!(path.points.back() == path.points.front())) {
        const std::int32_t id = takeEndAt(path.points.back(), true);
        if (id == PointMultimap::kNone)
            return false;
        const FacetSegment& segment = segments[segmentOf(id)];
        const bool along = isStartEnd(id);
        (along ? path.along_facets_um : path.against_facets_um) += segmentLength(segment);
        path.points.push_back(along ? segment.to : segment.from);
    }
    path.points.pop_back();  // the closing point repeats the first
    return true;
}

void SegmentStitcher::extendBackward(StitchedPath& path, const std::vector<FacetSegment>& segments) {
    prefix_.clear();
    Point2 current = path.points.front();
    for (;;) {
        const std::int32_t id = takeEndAt(current, false);
        if (id == PointMultimap::kNone)
            break;
        const FacetSegment& segment = segments[segmentOf(id)];
        const bool along = !isStartEnd(id);  // the segment ends here, so walking towards here follows it
        (along ? path.along_facets_um : path.against_facets_um) += segmentLength(segment);
        current = along ? segment.from : segment.to;
        prefix_.push_back(current);
    }
    path.points.insert(path.points.begin(), prefix_.rbegin(), prefix_.rend());
}

StitchResult SegmentStitcher::stitch(const std::vector<FacetSegment>& segments, coord_um max_gap_um) {
    ends_.reset(2 * segments.size());
    used_.assign(segments.size(), 0);
    for (std::size_t i = 0; i < segments.size(); ++i) {
        if (segments[i].from == segments[i].to) {
            used_[i] = 1;  // zero length: nothing to chain
            continue;
        }
        ends_.insert(segments[i].from, static_cast<std::int32_t>(2 * i));
        ends_.insert(segments[i].to, static_cast<std::int32_t>(2 * i + 1));
    }
    StitchResult result;
    std::vector<StitchedPath> open_pieces;
    for (std::size_t i = 0; i < segments.size(); ++i) {
        if (used_[i])
            continue;
        used_[i] = 1;
        StitchedPath path{{segments[i].from, segments[i].to}, segmentLength(segments[i]), 0.0};
        if (extendForward(path, segments)) {
            result.loops.push_back(std::move(path));
        } else {
            extendBackward(path, segments);
            open_pieces.push_back(std::move(path));
        }
    }
    closeGaps(open_pieces, max_gap_um, result.loops);
    for (StitchedPath& piece : open_pieces)
        result.open_polylines.push_back(std::move(piece.points));
    return result;
}

}  // namespace mixengine
