#pragma once
// Meshes built in code for the slicing tests (no files): boxes, banded boxes, cylinders,
// octahedra and a large bumpy sphere, all in microns and welded like MeshBuilder's output.
// Facets are wound counter-clockwise seen from outside (`inverted` flips them, a cavity's winding).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <tuple>
#include <vector>

#include "mesh/Mesh.h"

namespace mixengine::test {

/// Collects triangles with welded vertices.
class MeshAssembler {
  public:
    std::uint32_t vertex(const Point3& p) {
        const auto key = std::make_tuple(p.x, p.y, p.z);
        const auto found = index_.find(key);
        if (found != index_.end())
            return found->second;
        const auto id = static_cast<std::uint32_t>(mesh_.vertices.size());
        mesh_.vertices.push_back(p);
        index_.emplace(key, id);
        return id;
    }
    /// Adds (a, b, c) wound so that its normal points away from `inside` (or towards it when
    /// `inverted`).
    void triangle(const Point3& a, const Point3& b, const Point3& c, const Point3& inside,
                  bool inverted = false) {
        const double ux = double(b.x - a.x), uy = double(b.y - a.y), uz = double(b.z - a.z);
        const double vx = double(c.x - a.x), vy = double(c.y - a.y), vz = double(c.z - a.z);
        const double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
        const double out =
            nx * double(a.x - inside.x) + ny * double(a.y - inside.y) + nz * double(a.z - inside.z);
        const bool flip = (out < 0) != inverted;
        mesh_.faces.push_back(flip ? Face{{vertex(a), vertex(c), vertex(b)}}
                                   : Face{{vertex(a), vertex(b), vertex(c)}});
    }
    /// A planar quad a-b-c-d (in order around it) as two triangles.
    void quad(const Point3& a, const Point3& b, const Point3& c, const Point3& d, const Point3& inside,
              bool inverted = false) {
        triangle(a, b, c, inside, inverted);
        triangle(a, c, d, inside, inverted);
    }
    Mesh take(std::string name) {
        mesh_.name = std::move(name);
        return std::move(mesh_);
    }

  private:
    Mesh mesh_;
    std::map<std::tuple<coord_um, coord_um, coord_um>, std::uint32_t> index_;
};

/// Side faces of an axis-aligned box between z levels (one band).
inline void addBoxBand(MeshAssembler& m, const Point3& lo, const Point3& hi, coord_um z0, coord_um z1,
                       const Point3& inside, bool inverted) {
    const std::array<std::pair<coord_um, coord_um>, 4> corners{
        {{lo.x, lo.y}, {hi.x, lo.y}, {hi.x, hi.y}, {lo.x, hi.y}}};
    for (std::size_t i = 0; i < 4; ++i) {
        const auto [x0, y0] = corners[i];
        const auto [x1, y1] = corners[(i + 1) % 4];
        m.quad({x0, y0, z0}, {x1, y1, z0}, {x1, y1, z1}, {x0, y0, z1}, inside, inverted);
    }
}

/// An axis-aligned box; the side faces are split into bands every `band` microns in z (0: none).
inline void addBox(MeshAssembler& m, const Point3& lo, const Point3& hi, bool inverted = false,
                   coord_um band = 0) {
    const Point3 inside{(lo.x + hi.x) / 2, (lo.y + hi.y) / 2, (lo.z + hi.z) / 2};
    m.quad({lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z}, inside, inverted);
    m.quad({lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}, inside, inverted);
    const coord_um step = band > 0 ? band : hi.z - lo.z;
    for (coord_um z = lo.z; z < hi.z; z += step)
        addBoxBand(m, lo, hi, z, std::min(z + step, hi.z), inside, inverted);
}

inline Mesh box(const Point3& lo, const Point3& hi, coord_um band = 0) {
    MeshAssembler m;
    addBox(m, lo, hi, false, band);
    return m.take("box");
}

/// Vertices of a regular n-gon of radius r (rounded to microns), counter-clockwise.
inline Path regularPolygon(int n, coord_um radius, coord_um cx = 0, coord_um cy = 0) {
    Path ring;
    for (int i = 0; i < n; ++i) {
        const double angle = 2.0 * std::numbers::pi * i / n;
        ring.push_back(
            {cx + std::llround(radius * std::cos(angle)), cy + std::llround(radius * std::sin(angle))});
    }
    return ring;
}

/// A prism over a regular n-gon (caps fanned from the centre): 4n triangles.
inline Mesh cylinder(int n, coord_um radius, coord_um height) {
    MeshAssembler m;
    const Path ring = regularPolygon(n, radius);
    const Point3 inside{0, 0, height / 2};
    for (int i = 0; i < n; ++i) {
        const Point2& a = ring[i];
        const Point2& b = ring[(i + 1) % n];
        m.quad({a.X, a.Y, 0}, {b.X, b.Y, 0}, {b.X, b.Y, height}, {a.X, a.Y, height}, inside);
        m.triangle({0, 0, 0}, {a.X, a.Y, 0}, {b.X, b.Y, 0}, inside);
        m.triangle({0, 0, height}, {a.X, a.Y, height}, {b.X, b.Y, height}, inside);
    }
    return m.take("cylinder");
}

/// A regular octahedron centred at `c` with vertices at distance r along the axes.
inline Mesh octahedron(const Point3& c, coord_um r) {
    MeshAssembler m;
    const std::array<Point3, 4> equator{
        {{c.x + r, c.y, c.z}, {c.x, c.y + r, c.z}, {c.x - r, c.y, c.z}, {c.x, c.y - r, c.z}}};
    for (std::size_t i = 0; i < 4; ++i) {
        m.triangle(equator[i], equator[(i + 1) % 4], {c.x, c.y, c.z + r}, c);
        m.triangle(equator[i], equator[(i + 1) % 4], {c.x, c.y, c.z - r}, c);
    }
    return m.take("octahedron");
}

/// A square pyramid: base [−half, half]² at z = 0, apex at (0, 0, height).
inline Mesh pyramid(coord_um half, coord_um height) {
    MeshAssembler m;
    const Point3 inside{0, 0, height / 4};
    const Point3 apex{0, 0, height};
    const std::array<Point3, 4> base{
        {{-half, -half, 0}, {half, -half, 0}, {half, half, 0}, {-half, half, 0}}};
    m.quad(base[0], base[1], base[2], base[3], inside);
    for (std::size_t i = 0; i < 4; ++i)
        m.triangle(base[i], base[(i + 1) % 4], apex, inside);
    return m.take("pyramid");
}

/// A closed, bumpy UV sphere with 2·rings·segments − 2·segments triangles, indexed directly
/// (fast for ~10⁶ triangles). Centred on the z axis, standing on z = 0; height ≈ 2·radius.
inline Mesh bumpySphere(int rings, int segments, coord_um radius) {
    Mesh mesh;
    mesh.name = "bumpy sphere";
    const coord_um cz = radius * 11 / 10;
    mesh.vertices.push_back({0, 0, cz - radius});  // south pole
    for (int i = 1; i < rings; ++i) {
        const double theta = std::numbers::pi * i / rings;
        for (int j = 0; j < segments; ++j) {
            const double phi = 2.0 * std::numbers::pi * j / segments;
            const double r = radius * (1.0 + 0.08 * std::sin(7 * theta) * std::cos(5 * phi));
            mesh.vertices.push_back({std::llround(r * std::sin(theta) * std::cos(phi)),
                                     std::llround(r * std::sin(theta) * std::sin(phi)),
                                     cz - std::llround(r * std::cos(theta))});
        }
    }
    mesh.vertices.push_back({0, 0, cz + radius});  // north pole
    const auto north = static_cast<std::uint32_t>(mesh.vertices.size() - 1);
    auto at = [&](int ring, int seg) {
        return static_cast<std::uint32_t>(1 + (ring - 1) * segments + (seg % segments));
    };
    for (int j = 0; j < segments; ++j) {
        mesh.faces.push_back({{0, at(1, j + 1), at(1, j)}});
        mesh.faces.push_back({{north, at(rings - 1, j), at(rings - 1, j + 1)}});
        for (int i = 1; i + 1 < rings; ++i) {
            mesh.faces.push_back({{at(i, j), at(i, j + 1), at(i + 1, j + 1)}});
            mesh.faces.push_back({{at(i, j), at(i + 1, j + 1), at(i + 1, j)}});
        }
    }
    mesh.translate(0, 0, -mesh.bounds().min.z);
    return mesh;
}

}  // namespace mixengine::test
