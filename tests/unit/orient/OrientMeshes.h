#pragma once
// Meshes for the orientation tests: boxes (closed, open, two overlapping = self-intersecting),
// and a subdivided octahedron projected on a sphere.
#include <cmath>
#include <map>

#include "mesh/Mesh.h"

namespace mixengine::orient::test {

/// An axis-aligned box, facets counter-clockwise seen from outside.
inline Mesh boxMesh(const Vec3& min_mm, const Vec3& size_mm, const std::string& name = "box") {
    Mesh mesh;
    mesh.name = name;
    for (int i = 0; i < 8; ++i) {
        mesh.vertices.push_back({mmToMicrons(min_mm.x + ((i >> 2) & 1) * size_mm.x),
                                 mmToMicrons(min_mm.y + ((i >> 1) & 1) * size_mm.y),
                                 mmToMicrons(min_mm.z + (i & 1) * size_mm.z)});
    }
    // Quads by corner index (x bit 4, y bit 2, z bit 1), outward winding.
    const int quads[6][4] = {{0, 2, 6, 4}, {1, 5, 7, 3}, {0, 4, 5, 1},
                             {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 6, 7, 5}};
    for (const auto& q : quads) {
        mesh.faces.push_back({{static_cast<std::uint32_t>(q[0]), static_cast<std::uint32_t>(q[1]),
                               static_cast<std::uint32_t>(q[2])}});
        mesh.faces.push_back({{static_cast<std::uint32_t>(q[0]), static_cast<std::uint32_t>(q[2]),
                               static_cast<std::uint32_t>(q[3])}});
    }
    return mesh;
}

/// The box without its top (two facets removed): open.
inline Mesh openBox(const Vec3& min_mm, const Vec3& size_mm) {
    Mesh mesh = boxMesh(min_mm, size_mm, "open box");
    mesh.faces.erase(mesh.faces.begin() + 2, mesh.faces.begin() + 4);
    return mesh;
}

/// Two overlapping boxes in one mesh: closed, but self-intersecting.
inline Mesh overlappingBoxes() {
    Mesh a = boxMesh({0, 0, 0}, {20, 20, 20}, "overlapping boxes");
    const Mesh b = boxMesh({10, 10, 10}, {20, 20, 20});
    const auto base = static_cast<std::uint32_t>(a.vertices.size());
    a.vertices.insert(a.vertices.end(), b.vertices.begin(), b.vertices.end());
    for (const Face& f : b.faces)
        a.faces.push_back({{base + f.v[0], base + f.v[1], base + f.v[2]}});
    return a;
}

/// A sphere of radius r: an octahedron subdivided `levels` times, vertices pushed to the sphere.
inline Mesh sphereMesh(double r_mm, int levels) {
    std::vector<Vec3> v = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    std::vector<std::array<int, 3>> f = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                         {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    for (int l = 0; l < levels; ++l) {
        std::map<std::pair<int, int>, int> mid;
        auto middle = [&](int a, int b) {
            const auto key = std::minmax(a, b);
            if (const auto it = mid.find(key); it != mid.end())
                return it->second;
            const Vec3 m = (v[a] + v[b]) * 0.5;
            v.push_back(m * (1.0 / length(m)));
            return mid[key] = static_cast<int>(v.size()) - 1;
        };
        std::vector<std::array<int, 3>> next;
        for (const auto& t : f) {
            const int ab = middle(t[0], t[1]), bc = middle(t[1], t[2]), ca = middle(t[2], t[0]);
            next.push_back({t[0], ab, ca});
            next.push_back({ab, t[1], bc});
            next.push_back({ca, bc, t[2]});
            next.push_back({ab, bc, ca});
        }
        f = next;
    }
    Mesh mesh;
    mesh.name = "sphere";
    for (const Vec3& p : v)
        mesh.vertices.push_back({mmToMicrons(p.x * r_mm), mmToMicrons(p.y * r_mm), mmToMicrons(p.z * r_mm)});
    for (const auto& t : f)
        mesh.faces.push_back({{static_cast<std::uint32_t>(t[0]), static_cast<std::uint32_t>(t[1]),
                               static_cast<std::uint32_t>(t[2])}});
    return mesh;
}

/// Seed 000's analytic covariogram of a box with edges s: ∏ max(0, sᵢ − |vᵢ|).
inline double boxCovariogram(const Vec3& s, const Vec3& v) {
    return std::max(0.0, s.x - std::abs(v.x)) * std::max(0.0, s.y - std::abs(v.y)) *
           std::max(0.0, s.z - std::abs(v.z));
}

}  // namespace mixengine::orient::test
