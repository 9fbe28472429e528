#include "toolpaths/infill/ZigZag.h"

#include <algorithm>
#include <cmath>

#include "toolpaths/infill/LineFrame.h"
#include "toolpaths/infill/ScanCrossings.h"

namespace mixengine {
namespace {

struct Crossing : ScanCrossing {
    long scan_partner = -1;
    long boundary_next = -1;  ///< kept boundary piece from this crossing to that one
    long boundary_prev = -1;
};

/// The crossings of the scanlines with the polygons (toolpaths/infill/ScanCrossings.h), paired per scanline.
std::vector<Crossing> pairedCrossings(const Paths& polys, coord_um d, coord_um shift) {
    const std::vector<ScanCrossing> found = findScanCrossings(polys, d, shift);
    const std::vector<long> partner = pairOnScanlines(found);
    std::vector<Crossing> cs(found.size());
    for (std::size_t i = 0; i < found.size(); ++i) {
        static_cast<ScanCrossing&>(cs[i]) = found[i];
        cs[i].scan_partner = partner[i];
    }
    return cs;
}

/// Calls visit(from, to) for every pair of consecutive crossings along each polygon, indices into
/// `cs` (crossings are stored per polygon in walking order; the last one wraps to the first).
template <typename Visit>
void forEachBoundaryStep(const std::vector<Crossing>& cs, Visit&& visit) {
    std::size_t begin = 0;
    while (begin < cs.size()) {
        std::size_t end = begin;
        while (end < cs.size() && cs[end].polygon == cs[begin].polygon)
            ++end;
        const std::size_t n = end - begin;
        for (std::size_t j = 0; j < n && n > 1; ++j)
            visit(begin + j, begin + (j + 1) % n);
        begin = end;
    }
}

/// Whether the connection from scanline `from` to its neighbour `to` is one of the skipped ones.
bool skipped(long long from, long long to, int zag_skip_count) {
    if (zag_skip_count <= 0)
        return false;
    return (to > from ? from : from - 1) % zag_skip_count == 0;
}

/// Keep the alternate boundary pieces between scanlines.
void linkBoundary(std::vector<Crossing>& cs, int zag_skip_count) {
    forEachBoundaryStep(cs, [&cs, zag_skip_count](std::size_t i, std::size_t k) {
        Crossing& from = cs[i];
        Crossing& to = cs[k];
        if (from.line % 2 == 0 && std::llabs(to.line - from.line) == 1 && from.scan_partner >= 0 &&
            to.scan_partner >= 0 && !skipped(from.line, to.line, zag_skip_count)) {
            from.boundary_next = static_cast<long>(k);
            to.boundary_prev = static_cast<long>(i);
        }
    });
}

/// The polygon vertices strictly between crossing `from` and the next crossing `to` (same polygon,
/// walking order).
Path interiorOf(const Paths& polys, const Crossing& from, const Crossing& to) {
    const Path& poly = polys[from.polygon];
    Path inner;
    if (from.edge == to.edge && to.along >= from.along)
        return inner;
    std::size_t e = from.edge;
    for (std::size_t guard = 0; guard < poly.size(); ++guard) {
        e = (e + 1) % poly.size();
        inner.push_back(poly[e]);
        if (e == to.edge)
            break;
    }
    return inner;
}

Paths chain(const Paths& polys, std::vector<Crossing>& cs) {
    Paths lines;
    std::vector<bool> used(cs.size(), false);
    auto walk = [&](std::size_t start) {
        Path line{cs[start].point};
        std::size_t at = start;
        while (true) {
            used[at] = true;
            const long partner = cs[at].scan_partner;
            if (partner < 0 || used[std::size_t(partner)])
                break;
            at = std::size_t(partner);
            used[at] = true;
            line.push_back(cs[at].point);
            const long next = cs[at].boundary_next >= 0 ? cs[at].boundary_next : cs[at].boundary_prev;
            if (next < 0 || used[std::size_t(next)])
                break;
            const bool forward = cs[at].boundary_next >= 0;
            Path inner = forward ? interiorOf(polys, cs[at], cs[std::size_t(next)])
                                 : interiorOf(polys, cs[std::size_t(next)], cs[at]);
            if (!forward)
                std::reverse(inner.begin(), inner.end());
            line.insert(line.end(), inner.begin(), inner.end());
            at = std::size_t(next);
            line.push_back(cs[at].point);
        }
        lines.push_back(std::move(line));
    };
    for (std::size_t i = 0; i < cs.size(); ++i) {  // chain ends first: no boundary piece
        if (!used[i] && cs[i].scan_partner >= 0 && cs[i].boundary_next < 0 && cs[i].boundary_prev < 0)
            walk(i);
    }
    for (std::size_t i = 0; i < cs.size(); ++i) {  // what is left are cycles
        if (!used[i] && cs[i].scan_partner >= 0)
            walk(i);
    }
    return lines;
}

/// Boundary pieces between consecutive crossings of the same scanline, as separate polylines; open:
/// without their last line.
void appendEndPieces(const Paths& polys, const std::vector<Crossing>& cs, bool open, Paths& lines) {
    forEachBoundaryStep(cs, [&](std::size_t i, std::size_t k) {
        const Crossing& from = cs[i];
        const Crossing& to = cs[k];
        if (from.line != to.line || from.scan_partner < 0 || to.scan_partner < 0)
            return;
        Path piece{from.point};
        const Path inner = interiorOf(polys, from, to);
        piece.insert(piece.end(), inner.begin(), inner.end());
        if (!open)
            piece.push_back(to.point);
        if (piece.size() >= 2)
            lines.push_back(std::move(piece));
    });
}

/// The polygons no scanline crosses, whole (from their last vertex round to it again); open: without
/// their last line.
void appendUncrossed(const Paths& polys, const std::vector<Crossing>& cs, bool open, Paths& lines) {
    std::vector<bool> crossed(polys.size(), false);
    for (const Crossing& c : cs)
        crossed[c.polygon] = true;
    for (std::size_t i = 0; i < polys.size(); ++i) {
        if (crossed[i] || polys[i].size() < 2)
            continue;
        Path piece{polys[i].back()};
        piece.insert(piece.end(), polys[i].begin(), polys[i].end() - (open ? 1 : 0));
        lines.push_back(std::move(piece));
    }
}

}  // namespace

Paths zigzagLines(const Paths& area, coord_um d, double angle_degrees, coord_um shift_um, ZigzagEnds ends,
                  int zag_skip_count) {
    if (d <= 0 || area.empty())
        return {};
    const LineFrame frame(angle_degrees);  // the scanlines are vertical in it
    const Paths rotated = frame.into(area);
    const coord_um shift = linePhase(shift_um, d);
    std::vector<Crossing> cs = pairedCrossings(rotated, d, shift);
    linkBoundary(cs, zag_skip_count);
    Paths lines = chain(rotated, cs);
    if (ends != ZigzagEnds::None) {
        appendEndPieces(rotated, cs, ends == ZigzagEnds::Open, lines);
        appendUncrossed(rotated, cs, ends == ZigzagEnds::Open, lines);
    }
    frame.back(lines);
    return lines;
}

}  // namespace mixengine
