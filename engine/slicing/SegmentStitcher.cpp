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

/// Signed turn (radians, left positive) from the direction came_from→at to the direction at→next.
double turnAngle(const Point2& came_from, const Point2& at, const Point2& next) {
    const double in_x = static_cast<double>(at.X - came_from.X);
    const double in_y = static_cast<double>(at.Y - came_from.Y);
    const double out_x = static_cast<double>(next.X - at.X);
    const double out_y = static_cast<double>(next.Y - at.Y);
    return std::atan2(in_x * out_y - in_y * out_x, in_x * out_x + in_y * out_y);
}

}  // namespace

std::int32_t SegmentStitcher::chooseAmongEnds(const Point2& came_from, const Point2& point, bool forward,
                                              const std::vector<FacetSegment>& segments) const {
    std::int32_t best = PointMultimap::kNone;
    bool best_preferred = false;
    double best_turn = 0;
    for (std::int32_t id = ends_.first(point); id != PointMultimap::kNone; id = ends_.nextAtSamePoint(id)) {
        if (used_[segmentOf(id)])
            continue;
        const bool preferred = isStartEnd(id) == forward;
        if (best_preferred && !preferred)
            continue;
        const FacetSegment& segment = segments[segmentOf(id)];
        const double turn = turnAngle(came_from, point, isStartEnd(id) ? segment.to : segment.from);
        const double towards_solid = forward ? turn : -turn;
        if (best == PointMultimap::kNone || (preferred && !best_preferred) || towards_solid > best_turn) {
            best = id;
            best_preferred = preferred;
            best_turn = towards_solid;
        }
    }
    return best;
}

std::int32_t SegmentStitcher::takeEndAt(const Point2& came_from, const Point2& point, bool forward,
                                        const std::vector<FacetSegment>& segments) {
    std::int32_t only = PointMultimap::kNone;
    int unused = 0;
    for (std::int32_t id = ends_.first(point); id != PointMultimap::kNone; id = ends_.nextAtSamePoint(id)) {
        if (used_[segmentOf(id)])
            continue;
        only = id;
        ++unused;
    }
    const std::int32_t taken = unused > 1 ? chooseAmongEnds(came_from, point, forward, segments) : only;
    if (taken != PointMultimap::kNone)
        used_[segmentOf(taken)] = 1;
    return taken;
}

bool SegmentStitcher::extendForward(StitchedPath& path, const std::vector<FacetSegment>& segments) {
    while (!(exact_.back() == exact_.front())) {
        const std::int32_t id = takeEndAt(exact_[exact_.size() - 2], exact_.back(), true, segments);
        if (id == PointMultimap::kNone)
            return false;
        const FacetSegment& segment = segments[segmentOf(id)];
        const bool along = isStartEnd(id);
        (along ? path.along_facets_um : path.against_facets_um) += segmentLength(segment);
        exact_.push_back(along ? segment.to : segment.from);
        path.points.push_back(along ? segment.printed_to : segment.printed_from);
    }
    // CuraEngine keeps the closing point (the first segment's start as computed from its facet, the
    // last one's end as computed from its own); only an exact repeat goes.
    if (path.points.back() == path.points.front())
        path.points.pop_back();
    return true;
}

void SegmentStitcher::extendBackward(StitchedPath& path, const std::vector<FacetSegment>& segments) {
    prefix_.clear();
    Point2 came_from = path.points[1];
    Point2 current = path.points.front();
    for (;;) {
        const std::int32_t id = takeEndAt(came_from, current, false, segments);
        if (id == PointMultimap::kNone)
            break;
        const FacetSegment& segment = segments[segmentOf(id)];
        const bool along = !isStartEnd(id);  // the segment ends here, so walking towards here follows it
        (along ? path.along_facets_um : path.against_facets_um) += segmentLength(segment);
        came_from = current;
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
        StitchedPath path{
            {segments[i].printed_from, segments[i].printed_to}, segmentLength(segments[i]), 0.0};
        exact_.assign({segments[i].from, segments[i].to});
        if (extendForward(path, segments)) {
            result.loops.push_back(std::move(path));
        } else {
            path.points = exact_;  // open pieces are joined on the exact points
            extendBackward(path, segments);
            open_pieces.push_back(std::move(path));
        }
    }
    const std::size_t whole_loops = result.loops.size();
    closeGaps(open_pieces, max_gap_um, result.loops);
    result.gap_closed_loops = result.loops.size() - whole_loops;
    for (StitchedPath& piece : open_pieces)
        result.open_polylines.push_back(std::move(piece.points));
    return result;
}

}  // namespace mixengine
