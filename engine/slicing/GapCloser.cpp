#include "slicing/GapCloser.h"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <tuple>
#include <utility>

namespace mixengine {
namespace {

/// Ends are numbered 2·piece (first point) and 2·piece + 1 (last point).
struct EndPair {
    coord_um distance_sq_um2;
    int end_a;
    int end_b;
};

Point2 endPoint(const std::vector<StitchedPath>& pieces, int end) {
    const Path& points = pieces[static_cast<std::size_t>(end / 2)].points;
    return end % 2 == 0 ? points.front() : points.back();
}

std::vector<EndPair> nearbyEndPairs(const std::vector<StitchedPath>& pieces, coord_um max_gap_um) {
    std::vector<int> ends(2 * pieces.size());
    std::iota(ends.begin(), ends.end(), 0);
    std::vector<Point2> at(ends.size());
    for (int end : ends)
        at[static_cast<std::size_t>(end)] = endPoint(pieces, end);
    std::sort(ends.begin(), ends.end(),
              [&](int a, int b) { return std::tie(at[a].X, a) < std::tie(at[b].X, b); });
    std::vector<EndPair> pairs;
    for (std::size_t i = 0; i < ends.size(); ++i) {
        const Point2& p = at[static_cast<std::size_t>(ends[i])];
        for (std::size_t j = i + 1; j < ends.size(); ++j) {
            const Point2& q = at[static_cast<std::size_t>(ends[j])];
            const coord_um dx = q.X - p.X;
            if (dx > max_gap_um)
                break;
            const coord_um dy = q.Y - p.Y;
            if (dy > max_gap_um || -dy > max_gap_um)
                continue;
            const coord_um distance_sq = dx * dx + dy * dy;
            if (distance_sq > max_gap_um * max_gap_um)
                continue;
            pairs.push_back({distance_sq, std::min(ends[i], ends[j]), std::max(ends[i], ends[j])});
        }
    }
    std::sort(pairs.begin(), pairs.end(), [](const EndPair& a, const EndPair& b) {
        return std::tie(a.distance_sq_um2, a.end_a, a.end_b) < std::tie(b.distance_sq_um2, b.end_a, b.end_b);
    });
    return pairs;
}

/// link[end] = the end it is joined to (−1: free). Greedy matching, nearest pairs first.
std::vector<int> linkEnds(const std::vector<EndPair>& pairs, std::size_t piece_count) {
    std::vector<int> link(2 * piece_count, -1);
    std::vector<int> partner(2 * piece_count);  // the other free end of the chain an end belongs to
    for (std::size_t end = 0; end < partner.size(); ++end)
        partner[end] = static_cast<int>(end ^ 1U);
    for (const EndPair& pair : pairs) {
        if (link[pair.end_a] != -1 || link[pair.end_b] != -1)
            continue;
        link[pair.end_a] = pair.end_b;
        link[pair.end_b] = pair.end_a;
        if (partner[pair.end_a] == pair.end_b)
            continue;  // the chain closes
        const int far_a = partner[pair.end_a];
        const int far_b = partner[pair.end_b];
        partner[far_a] = far_b;
        partner[far_b] = far_a;
    }
    return link;
}

void appendPiece(StitchedPath& chain, const StitchedPath& piece, bool reversed) {
    const std::size_t old_size = chain.points.size();
    if (reversed) {
        chain.points.insert(chain.points.end(), piece.points.rbegin(), piece.points.rend());
    } else {
        chain.points.insert(chain.points.end(), piece.points.begin(), piece.points.end());
    }
    if (old_size > 0 && chain.points[old_size - 1] == chain.points[old_size]) {
        chain.points.erase(chain.points.begin() + static_cast<std::ptrdiff_t>(old_size));
    }
    chain.along_facets_um += reversed ? piece.against_facets_um : piece.along_facets_um;
    chain.against_facets_um += reversed ? piece.along_facets_um : piece.against_facets_um;
}

/// The end through which the chain containing `piece` is entered first; `closed` tells whether
/// the chain is a loop (then the piece's own first end is used).
int chainEntry(const std::vector<int>& link, std::size_t piece, bool& closed) {
    const int own_entry = static_cast<int>(2 * piece);
    int entry = own_entry;
    closed = false;
    while (link[entry] != -1) {
        const int previous_entry = link[entry] ^ 1;
        if (previous_entry == own_entry) {
            closed = true;
            return own_entry;
        }
        entry = previous_entry;
    }
    return entry;
}

}  // namespace

void closeGaps(std::vector<StitchedPath>& open_pieces, coord_um max_gap_um,
               std::vector<StitchedPath>& loops) {
    if (open_pieces.empty() || max_gap_um < 0)
        return;
    const std::vector<int> link = linkEnds(nearbyEndPairs(open_pieces, max_gap_um), open_pieces.size());
    std::vector<char> done(open_pieces.size(), 0);
    std::vector<StitchedPath> still_open;
    for (std::size_t i = 0; i < open_pieces.size(); ++i) {
        if (done[i])
            continue;
        bool closed = false;
        const int entry = chainEntry(link, i, closed);
        StitchedPath chain;
        for (int end = entry;;) {
            const auto piece = static_cast<std::size_t>(end / 2);
            appendPiece(chain, open_pieces[piece], end % 2 == 1);
            done[piece] = 1;
            end = link[end ^ 1];
            if (end == -1 || (closed && end == entry))
                break;
        }
        if (closed && chain.points.size() > 1 && chain.points.front() == chain.points.back()) {
            chain.points.pop_back();
        }
        (closed ? loops : still_open).push_back(std::move(chain));
    }
    open_pieces = std::move(still_open);
}

}  // namespace mixengine
