#include "mesh/build/MeshBuilder.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "common/Error.h"
#include "mesh/MemoryHint.h"
#include "mesh/build/FaceSet.h"
#include "mesh/build/VertexWelder.h"

namespace mixengine {

namespace {

/// |coordinate| limit: 1 km. Keeps integer cross products exact in 64 bits, coordinates within
/// int32 for the welder and within Clipper's fast range.
constexpr double kMaxAbsMicrons = 1e9;

/// Triangles handled together so that their hash-table cache misses overlap (prefetching).
constexpr std::size_t kBatch = 64;

Point3 quantise(const Vec3& mm, const std::string& part) {
    const double um[3] = {mm.x * kMicronsPerMm, mm.y * kMicronsPerMm, mm.z * kMicronsPerMm};
    for (const double value : um) {
        if (!(std::fabs(value) <= kMaxAbsMicrons)) {  // also rejects NaN
            throw InputError(part + ": vertex coordinate " + std::to_string(value / kMicronsPerMm) +
                             " mm (after the mesh transform) is outside +-1000000 mm");
        }
    }
    return {std::llround(um[0]), std::llround(um[1]), std::llround(um[2])};
}

/// Zero area in integer space (covers two equal corners). Exact: |deltas| <= 2e9, products <= 4e18.
bool zeroArea(const Point3& a, const Point3& b, const Point3& c) {
    const Point3 u{b.x - a.x, b.y - a.y, b.z - a.z};
    const Point3 v{c.x - a.x, c.y - a.y, c.z - a.z};
    return u.y * v.z == u.z * v.y && u.z * v.x == u.x * v.z && u.x * v.y == u.y * v.x;
}

class MeshAssembler {
  public:
    MeshAssembler(const TriangleSoup& soup, const Matrix3& transform, const std::string& label)
        : soup_(soup),
          transform_(transform),
          label_(label.empty() ? soup.name : label),
          welder_(soup.triangles.size() / 2 + 16),
          seen_(soup.triangles.size()) {
        mesh_.name = soup.name;
        mesh_.faces.reserve(soup.triangles.size());
        adviseHugePages(mesh_.faces.data(), mesh_.faces.capacity() * sizeof(Face));
        stats_.input_triangles = soup.triangles.size();
    }

    /// Adds soup triangles [first, first + count), count <= kBatch.
    void addBatch(std::size_t first, std::size_t count) {
        quantiseBatch(first, count);
        const std::size_t candidates = weldBatch(first, count);
        keepNewFaces(candidates);
    }

    Mesh finish(MeshBuildStats* stats) {
        mesh_.vertices = welder_.takeVertices();
        stats_.welded_vertices = mesh_.vertices.size();
        if (stats != nullptr) {
            *stats = stats_;
        }
        return std::move(mesh_);
    }

  private:
    void quantiseBatch(std::size_t first, std::size_t count) {
        for (std::size_t i = 0; i < count; ++i) {
            for (std::size_t k = 0; k < 3; ++k) {
                points_[3 * i + k] = quantise(transform_.apply(soup_.triangles[first + i][k]), label_);
                welder_.prefetch(points_[3 * i + k]);
            }
        }
    }

    /// Welds the corners of non-degenerate triangles; returns how many candidate faces it made.
    std::size_t weldBatch(std::size_t first, std::size_t count) {
        std::size_t made = 0;
        for (std::size_t i = 0; i < count; ++i) {
            const Point3* p = &points_[3 * i];
            if (zeroArea(p[0], p[1], p[2])) {
                ++stats_.degenerate_dropped;
                continue;
            }
            candidates_[made] = Face{{welder_.indexOf(p[0]), welder_.indexOf(p[1]), welder_.indexOf(p[2])}};
            sources_[made] = first + i;
            seen_.prefetch(candidates_[made]);
            ++made;
        }
        return made;
    }

    void keepNewFaces(std::size_t candidates) {
        for (std::size_t i = 0; i < candidates; ++i) {
            if (seen_.insert(candidates_[i])) {
                mesh_.faces.push_back(candidates_[i]);
                if (!soup_.colors.empty())
                    mesh_.face_colors.push_back(soup_.colors[sources_[i]]);
            } else {
                ++stats_.duplicates_dropped;
            }
        }
    }

    const TriangleSoup& soup_;
    const Matrix3& transform_;
    const std::string& label_;  ///< names the part in errors
    VertexWelder welder_;
    FaceSet seen_;
    Mesh mesh_;
    MeshBuildStats stats_;
    std::array<Point3, 3 * kBatch> points_;
    std::array<Face, kBatch> candidates_;
    std::array<std::size_t, kBatch> sources_;  ///< soup triangle of each candidate (its colour)
};

}  // namespace

Mesh buildMesh(const TriangleSoup& soup, const Matrix3& transform, MeshBuildStats* stats,
               const std::string& label) {
    const std::size_t count = soup.triangles.size();
    const std::string& part = label.empty() ? soup.name : label;
    if (count > std::numeric_limits<std::uint32_t>::max() / 3) {
        throw InputError(part + ": too many triangles (" + std::to_string(count) + ")");
    }
    MeshAssembler assembler(soup, transform, label);
    for (std::size_t first = 0; first < count; first += kBatch) {
        assembler.addBatch(first, std::min(kBatch, count - first));
    }
    return assembler.finish(stats);
}

}  // namespace mixengine
