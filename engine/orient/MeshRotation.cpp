#include "orient/MeshRotation.h"

#include <algorithm>
#include <cstring>

namespace mixengine::orient {
namespace {

coord_um lowestZ(const std::vector<Mesh*>& meshes) {
    coord_um z = INT64_MAX;
    for (const Mesh* mesh : meshes) {
        if (!mesh->faces.empty())
            z = std::min(z, mesh->bounds().min.z);
    }
    return z;
}

void appendFloat(std::string& out, double value) {
    const float f = static_cast<float>(value);
    char bytes[4];
    std::memcpy(bytes, &f, 4);
    out.append(bytes, 4);
}

Vec3 toMm(const Point3& p) {
    return {micronsToMm(p.x), micronsToMm(p.y), micronsToMm(p.z)};
}

}  // namespace

void rotateTogether(const std::vector<Mesh*>& meshes, const Matrix3& rotation, const Vec3& centre_mm) {
    const coord_um before = lowestZ(meshes);
    for (Mesh* mesh : meshes) {
        for (Point3& p : mesh->vertices) {
            const Vec3 q = centre_mm + rotation.apply(toMm(p) - centre_mm);
            p = {mmToMicrons(q.x), mmToMicrons(q.y), mmToMicrons(q.z)};
        }
    }
    const coord_um after = lowestZ(meshes);
    if (before == INT64_MAX)
        return;
    for (Mesh* mesh : meshes)
        mesh->translate(0, 0, before - after);
}

Mesh concatenated(const std::vector<const Mesh*>& meshes, const std::string& name) {
    Mesh out;
    out.name = name;
    for (const Mesh* mesh : meshes) {
        const auto base = static_cast<std::uint32_t>(out.vertices.size());
        out.vertices.insert(out.vertices.end(), mesh->vertices.begin(), mesh->vertices.end());
        for (const Face& f : mesh->faces)
            out.faces.push_back({{base + f.v[0], base + f.v[1], base + f.v[2]}});
    }
    return out;
}

std::string binaryStl(const Mesh& mesh) {
    std::string out(80, '\0');
    const std::string header = "MixEngine orient: " + mesh.name;
    std::memcpy(out.data(), header.data(), std::min<std::size_t>(header.size(), 80));
    const auto count = static_cast<std::uint32_t>(mesh.faces.size());
    char bytes[4];
    std::memcpy(bytes, &count, 4);
    out.append(bytes, 4);
    for (const Face& f : mesh.faces) {
        const Vec3 a = toMm(mesh.vertices[f.v[0]]), b = toMm(mesh.vertices[f.v[1]]),
                   c = toMm(mesh.vertices[f.v[2]]);
        Vec3 n = cross(b - a, c - a);
        const double len = length(n);
        if (len > 0)
            n = n * (1.0 / len);
        for (const Vec3& v : {n, a, b, c}) {
            appendFloat(out, v.x);
            appendFloat(out, v.y);
            appendFloat(out, v.z);
        }
        out.append(2, '\0');
    }
    return out;
}

}  // namespace mixengine::orient
