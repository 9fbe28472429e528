#include "mixing/transition/PurgeTower.h"

#include <algorithm>
#include <cmath>

namespace mixengine {
namespace {

bool inside(const Point2& lo, const Point2& hi, const TowerSite& site) {
    return lo.X >= site.plate_min.X && lo.Y >= site.plate_min.Y && hi.X <= site.plate_max.X &&
           hi.Y <= site.plate_max.Y;
}

bool clear(const Point2& lo, const Point2& hi, const TowerSite& site) {
    const coord_um c = site.clearance_um;
    return hi.X < site.print_min.X - c || lo.X > site.print_max.X + c || hi.Y < site.print_min.Y - c ||
           lo.Y > site.print_max.Y + c;
}

}  // namespace

std::optional<Point2> placeTower(const TowerSite& site, coord_um side_um) {
    const coord_um half = side_um / 2;
    const coord_um gap = site.clearance_um + half + 1;
    const Point2 mid{(site.print_min.X + site.print_max.X) / 2, (site.print_min.Y + site.print_max.Y) / 2};
    std::vector<Point2> centres;
    if (site.preferred_anchor)
        centres.push_back({site.preferred_anchor->X - half, site.preferred_anchor->Y + half});
    centres.push_back({site.print_max.X + gap, mid.Y});
    centres.push_back({site.print_min.X - gap, mid.Y});
    centres.push_back({mid.X, site.print_max.Y + gap});
    centres.push_back({mid.X, site.print_min.Y - gap});
    for (const Point2& c : centres) {
        const Point2 lo{c.X - half, c.Y - half}, hi{c.X + half, c.Y + half};
        if (inside(lo, hi, site) && clear(lo, hi, site))
            return lo;
    }
    return std::nullopt;
}

Path towerPath(const PurgeTowerShape& shape, int layer_number) {
    Path path;
    const coord_um w = std::max<coord_um>(1, shape.line_width_um);
    const coord_um lo = w / 2, hi = shape.side_um - w / 2;
    const bool along_x = layer_number % 2 == 0;
    bool forward = true;
    for (coord_um across = lo; across <= hi; across += w) {
        const coord_um from = forward ? lo : hi, to = forward ? hi : lo;
        const Point2 a = along_x ? Point2{from, across} : Point2{across, from};
        const Point2 b = along_x ? Point2{to, across} : Point2{across, to};
        path.push_back({shape.min_corner.X + a.X, shape.min_corner.Y + a.Y});
        path.push_back({shape.min_corner.X + b.X, shape.min_corner.Y + b.Y});
        forward = !forward;
    }
    return path;
}

TowerCursor::TowerCursor(Path path, coord_um line_width_um, coord_um thickness_um)
    : path_(std::move(path)), mm3_per_um_(micronsToMm(line_width_um) * micronsToMm(thickness_um) / 1000.0) {
    if (!path_.empty())
        at_ = path_.front();
    for (std::size_t i = 1; i < path_.size(); ++i)
        left_mm3_ += distanceUm(path_[i - 1], path_[i]) * mm3_per_um_;
}

double TowerCursor::volumeLeftMm3() const {
    return left_mm3_;
}

void TowerCursor::emit(double volume_mm3, const PlanStep& travel, const PlanStep& extrude,
                       std::vector<PlanStep>& out) {
    double want = std::min(volume_mm3, left_mm3_);
    if (want <= 1e-9 || path_.size() < 2)
        return;
    PlanStep go = travel;
    go.to = at_;
    go.retract = true;
    go.prime_first = false;
    out.push_back(go);
    while (want > 1e-9 && segment_ + 1 < path_.size()) {
        const Point2 end = path_[segment_ + 1];
        const double here_mm3 = distanceUm(at_, end) * mm3_per_um_;
        PlanStep step = extrude;
        if (here_mm3 <= want + 1e-9) {
            step.to = end;
            step.volume_mm3 = here_mm3;
            ++segment_;
        } else {
            const double f = want / here_mm3;
            step.to = {at_.X + std::llround(f * double(end.X - at_.X)),
                       at_.Y + std::llround(f * double(end.Y - at_.Y))};
            step.volume_mm3 = want;
        }
        want -= step.volume_mm3;
        left_mm3_ -= step.volume_mm3;
        at_ = step.to;
        out.push_back(step);
    }
}

}  // namespace mixengine
