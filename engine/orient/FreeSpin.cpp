#include "orient/FreeSpin.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "geometry/Angles.h"

namespace mixengine::orient {
namespace {

constexpr double kBedToleranceMm = 0.05;

enum class Key { Contact, Height, Overhang };

double keyValue(const SpinScore& s, Key key) {  // smaller is better
    switch (key) {
        case Key::Contact:
            return -s.contact_mm2;
        case Key::Height:
            return s.height_mm;
        case Key::Overhang:
            return s.overhang_mm2;
    }
    return 0;
}

double keyTolerance(double best, Key key) {
    return key == Key::Height ? 0.1 : std::max(1.0, 0.01 * std::abs(best));
}

std::string keyName(Key key) {
    switch (key) {
        case Key::Contact:
            return "flat face";
        case Key::Height:
            return "low height";
        case Key::Overhang:
            return "low overhang";
    }
    return "";
}

std::vector<Key> keyOrder(Objective objective) {
    switch (objective) {
        case Objective::FlatFace:
            return {Key::Contact, Key::Overhang, Key::Height};
        case Objective::LowHeight:
            return {Key::Height, Key::Overhang, Key::Contact};
        case Objective::LowOverhang:
            return {Key::Overhang, Key::Height, Key::Contact};
    }
    return {};
}

/// True when every option is the same candidate with spins within 1° of each other.
bool singleChoice(const std::vector<SpinOption>& options) {
    for (const SpinOption& o : options) {
        const double gap = std::abs(std::remainder(o.score.spin_deg - options.front().score.spin_deg, 360.0));
        if (o.candidate != options.front().candidate || gap > 1.0)
            return false;
    }
    return true;
}

}  // namespace

SurfaceSample::SurfaceSample(const std::vector<const Mesh*>& meshes) {
    for (const Mesh* mesh : meshes) {
        const auto base = static_cast<std::uint32_t>(vertices_.size());
        for (const Point3& p : mesh->vertices)
            vertices_.push_back({micronsToMm(p.x), micronsToMm(p.y), micronsToMm(p.z)});
        for (const Face& f : mesh->faces) {
            const std::array<std::uint32_t, 3> idx{base + f.v[0], base + f.v[1], base + f.v[2]};
            const Vec3 n =
                cross(vertices_[idx[1]] - vertices_[idx[0]], vertices_[idx[2]] - vertices_[idx[0]]);
            const double twice_area = length(n);
            if (twice_area <= 0)
                continue;
            faces_.push_back(idx);
            normals_.push_back(n * (1.0 / twice_area));
            areas_.push_back(0.5 * twice_area);
            total_area_ += 0.5 * twice_area;
        }
    }
}

SpinScore SurfaceSample::score(const Matrix3& r, double overhang_angle_deg) const {
    SpinScore s;
    std::vector<double> z(vertices_.size());
    double lo = 1e300, hi = -1e300;
    for (std::size_t i = 0; i < vertices_.size(); ++i) {
        const Vec3& p = vertices_[i];
        z[i] = r.m[2][0] * p.x + r.m[2][1] * p.y + r.m[2][2] * p.z;
        lo = std::min(lo, z[i]);
        hi = std::max(hi, z[i]);
    }
    s.height_mm = vertices_.empty() ? 0 : hi - lo;
    const double flat = std::cos(0.5 * kRadiansPerDegree),
                 steep = std::sin(overhang_angle_deg * kRadiansPerDegree);
    for (std::size_t f = 0; f < faces_.size(); ++f) {
        const Vec3& n = normals_[f];
        const double nz = r.m[2][0] * n.x + r.m[2][1] * n.y + r.m[2][2] * n.z;
        if (nz >= -steep)
            continue;
        const auto& v = faces_[f];
        const bool on_bed = nz < -flat && z[v[0]] - lo < kBedToleranceMm && z[v[1]] - lo < kBedToleranceMm &&
                            z[v[2]] - lo < kBedToleranceMm;
        if (on_bed)
            s.contact_mm2 += areas_[f];
        else
            s.overhang_mm2 += areas_[f] * -nz;
    }
    return s;
}

std::vector<Vec3> SurfaceSample::flatNormals(double min_share, int count) const {
    std::map<std::array<long, 3>, std::pair<double, Vec3>> groups;  // quantised normal -> area, sum
    for (std::size_t f = 0; f < faces_.size(); ++f) {
        const Vec3& n = normals_[f];
        const std::array<long, 3> key{std::lround(n.x * 100), std::lround(n.y * 100), std::lround(n.z * 100)};
        auto& [area, sum] = groups[key];
        area += areas_[f];
        sum = sum + n * areas_[f];
    }
    std::vector<std::pair<double, Vec3>> sorted;
    for (const auto& [key, group] : groups) {
        if (group.first >= min_share * total_area_)
            sorted.push_back({group.first, normalised(group.second)});
    }
    std::stable_sort(sorted.begin(), sorted.end(),
                     [](const auto& a, const auto& b) { return a.first > b.first; });
    std::vector<Vec3> normals;
    for (std::size_t i = 0; i < sorted.size() && static_cast<int>(i) < count; ++i)
        normals.push_back(sorted[i].second);
    return normals;
}

std::vector<double> spinsToTry(const LatLon& angles, const Vec3& d_unit,
                               const std::vector<Vec3>& flat_normals) {
    std::vector<double> spins;
    for (int s = 0; s < 360; ++s)
        spins.push_back(s);
    const Matrix3 base = seedRotation(angles.latitude_deg, angles.longitude_deg);
    const Vec3 down{0, 0, -1};
    for (const Vec3& n : flat_normals) {
        const Vec3 m = base.apply(n);
        if (std::abs(dot(m, d_unit)) > 1e-3)
            continue;  // this face cannot lie on the bed for this direction
        const double spin = std::atan2(dot(d_unit, cross(m, down)), dot(m, down)) / kRadiansPerDegree;
        spins.push_back(spin < 0 ? spin + 360.0 : spin);
    }
    return spins;
}

SpinOption chooseOption(const std::vector<SpinOption>& options, Objective objective, std::string& picked_by) {
    std::vector<SpinOption> left = options;
    const std::vector<Key> keys = keyOrder(objective);
    picked_by = keyName(keys.front());
    for (const Key key : keys) {  // picked_by: the last criterion that ruled options out
        if (singleChoice(left))
            break;
        double best = 1e300;
        for (const SpinOption& o : left)
            best = std::min(best, keyValue(o.score, key));
        const double tolerance = keyTolerance(best, key);
        if (std::erase_if(left,
                          [&](const SpinOption& o) { return keyValue(o.score, key) > best + tolerance; }) > 0)
            picked_by = keyName(key);
    }
    // Among what is left, the best by the first criterion, then the first in order.
    return *std::min_element(left.begin(), left.end(), [&](const SpinOption& a, const SpinOption& b) {
        return keyValue(a.score, keys.front()) < keyValue(b.score, keys.front());
    });
}

std::string objectiveName(Objective objective) {
    return keyName(keyOrder(objective).front());
}

}  // namespace mixengine::orient
