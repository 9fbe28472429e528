#include "toolpaths/infill/ConnectedLines.h"

#include <algorithm>
#include <numeric>
#include <optional>

#include "toolpaths/infill/LineFrame.h"
#include "toolpaths/infill/ScanCrossings.h"

namespace mixengine {
namespace {

/// One end of a segment, on an edge of the area.
struct End {
    Point2 point;  ///< in the area's own frame
    std::size_t polygon = 0;
    std::size_t edge = 0;
    double along = 0;
    std::size_t segment = 0;  ///< ends 2s and 2s + 1 belong to segment s
};

/// What is attached to an end: a connector to another end, or a tail.
struct Attachment {
    long other = -1;  ///< the end at the connector's far side; −1 for a tail
    Path path;        ///< from this end's point (connectors are stored at both ends)
};

class UnionFind {
  public:
    explicit UnionFind(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
    std::size_t find(std::size_t i) {
        while (parent_[i] != i)
            i = parent_[i] = parent_[parent_[i]];
        return i;
    }
    void unite(std::size_t a, std::size_t b) { parent_[find(a)] = find(b); }

  private:
    std::vector<std::size_t> parent_;
};

/// The segments of one line set as pairs of ends (appended to `ends`).
void appendSegments(const Paths& area, const LineSet& set, std::vector<End>& ends) {
    if (set.spacing_um <= 0)
        return;
    const LineFrame frame(set.angle_degrees);
    const std::vector<ScanCrossing> cs =
        findScanCrossings(frame.into(area), set.spacing_um, linePhase(set.phase_um, set.spacing_um));
    const std::vector<long> partner = pairOnScanlines(cs);
    for (std::size_t i = 0; i < cs.size(); ++i) {
        if (partner[i] <= static_cast<long>(i))
            continue;
        const ScanCrossing& a = cs[i];
        const ScanCrossing& b = cs[std::size_t(partner[i])];
        Paths points{{a.point, b.point}};
        frame.back(points);
        if (points[0][0] == points[0][1])
            continue;  // zero length once back in the area's frame
        const std::size_t segment = ends.size() / 2;
        ends.push_back({points[0][0], a.polygon, a.edge, a.along, segment});
        ends.push_back({points[0][1], b.polygon, b.edge, b.along, segment});
    }
}

/// The ends on each polygon in walking order: edges from the one ending at vertex 0, then along each.
std::vector<std::vector<std::size_t>> endsByPolygon(const Paths& area, const std::vector<End>& ends) {
    std::vector<std::vector<std::size_t>> by(area.size());
    for (std::size_t i = 0; i < ends.size(); ++i)
        by[ends[i].polygon].push_back(i);
    for (std::size_t p = 0; p < by.size(); ++p) {
        const std::size_t n = area[p].size();
        std::sort(by[p].begin(), by[p].end(), [&](std::size_t a, std::size_t b) {
            const std::size_t ka = (ends[a].edge + 1) % n, kb = (ends[b].edge + 1) % n;
            return ka != kb ? ka < kb : ends[a].along < ends[b].along;
        });
    }
    return by;
}

void appendPoint(Path& path, const Point2& p) {
    if (path.empty() || path.back() != p)
        path.push_back(p);
}

/// The walk along one polygon, adding connectors and tails.
class PolygonWalk {
  public:
    PolygonWalk(const std::vector<End>& ends, UnionFind& groups, std::vector<std::optional<Attachment>>& att)
        : ends_(ends), groups_(groups), att_(att) {}

    void run(const Path& poly, const std::vector<std::size_t>& order) {
        const std::size_t n = poly.size();
        std::size_t next = 0;
        for (std::size_t k = 0; k < n; ++k) {  // the edge ending at vertex k
            const std::size_t edge = (k + n - 1) % n;
            while (next < order.size() && ends_[order[next]].edge == edge)
                meet(order[next++]);
            if (from_ >= 0)
                passVertex(poly[k]);
        }
        stop();
    }

  private:
    void meet(std::size_t end) {
        if (from_ < 0) {
            from_ = static_cast<long>(end);
            pending_ = {ends_[end].point};
            return;
        }
        const std::size_t a = groups_.find(ends_[std::size_t(from_)].segment);
        const std::size_t b = groups_.find(ends_[end].segment);
        if (a == b)
            return;  // already joined: the connector goes on past it
        appendPoint(pending_, ends_[end].point);
        Path back(pending_.rbegin(), pending_.rend());
        att_[std::size_t(from_)] = Attachment{static_cast<long>(end), pending_};
        att_[end] = Attachment{from_, std::move(back)};
        groups_.unite(a, b);
        from_ = -1;
        pending_.clear();
    }

    void passVertex(const Point2& vertex) {
        if (pending_.back() == vertex) {
            stop();  // a segment ending exactly on the vertex: what was drawn stays as a tail
            return;
        }
        pending_.push_back(vertex);
    }

    void stop() {
        if (from_ >= 0 && pending_.size() > 1)
            att_[std::size_t(from_)] = Attachment{-1, pending_};
        from_ = -1;
        pending_.clear();
    }

    const std::vector<End>& ends_;
    UnionFind& groups_;
    std::vector<std::optional<Attachment>>& att_;
    long from_ = -1;
    Path pending_;
};

/// The chain starting at `start` (an end without a connector), as one polyline.
Path chainFrom(std::size_t start, const std::vector<End>& ends,
               const std::vector<std::optional<Attachment>>& att, std::vector<bool>& used) {
    Path line;
    if (att[start])
        line.assign(att[start]->path.rbegin(), att[start]->path.rend());  // its tail, towards the end
    std::size_t at = start;
    while (true) {
        appendPoint(line, ends[at].point);
        used[ends[at].segment] = true;
        const std::size_t far = at ^ 1U;  // the segment's other end
        appendPoint(line, ends[far].point);
        if (!att[far])
            break;
        for (const Point2& p : att[far]->path)
            appendPoint(line, p);
        if (att[far]->other < 0)
            break;
        at = std::size_t(att[far]->other);
    }
    return line;
}

}  // namespace

Paths connectedLines(const Paths& area, const std::vector<LineSet>& sets) {
    std::vector<End> ends;
    for (const LineSet& set : sets)
        appendSegments(area, set, ends);
    const std::size_t segments = ends.size() / 2;
    UnionFind groups(segments);
    std::vector<std::optional<Attachment>> att(ends.size());
    const std::vector<std::vector<std::size_t>> order = endsByPolygon(area, ends);
    for (std::size_t p = 0; p < area.size(); ++p) {
        PolygonWalk walk(ends, groups, att);
        walk.run(area[p], order[p]);
    }
    Paths lines;
    std::vector<bool> used(segments, false);
    for (std::size_t i = 0; i < ends.size(); ++i) {
        const bool chain_end = !att[i] || att[i]->other < 0;
        if (chain_end && !used[ends[i].segment])
            lines.push_back(chainFrom(i, ends, att, used));
    }
    return lines;
}

}  // namespace mixengine
