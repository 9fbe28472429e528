#include "slicing/FacetBuckets.h"

#include <algorithm>

#include "common/Error.h"

namespace mixengine {
namespace {

/// The planes [first, last) a facet spans.
struct PlaneRange {
    std::uint32_t first;
    std::uint32_t last;
};

PlaneRange planeRange(const Mesh& mesh, const Face& face, const std::vector<coord_um>& planes) {
    const coord_um z0 = mesh.vertices[face.v[0]].z;
    const coord_um z1 = mesh.vertices[face.v[1]].z;
    const coord_um z2 = mesh.vertices[face.v[2]].z;
    const coord_um min_z = std::min({z0, z1, z2});
    const coord_um max_z = std::max({z0, z1, z2});
    const auto first = std::lower_bound(planes.begin(), planes.end(), min_z);
    const auto last = std::upper_bound(first, planes.end(), max_z);
    return {static_cast<std::uint32_t>(first - planes.begin()),
            static_cast<std::uint32_t>(last - planes.begin())};
}

}  // namespace

FacetBuckets::FacetBuckets(const Mesh& mesh, const std::vector<coord_um>& plane_z_ascending)
    : offsets_(plane_z_ascending.size() + 1, 0) {
    if (!std::is_sorted(plane_z_ascending.begin(), plane_z_ascending.end())) {
        throw InternalError("FacetBuckets: plane heights are not ascending");
    }
    std::vector<PlaneRange> ranges(mesh.faces.size());
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        ranges[f] = planeRange(mesh, mesh.faces[f], plane_z_ascending);
        for (std::uint32_t p = ranges[f].first; p < ranges[f].last; ++p)
            ++offsets_[p + 1];
    }
    for (std::size_t p = 1; p < offsets_.size(); ++p)
        offsets_[p] += offsets_[p - 1];
    facets_.resize(offsets_.back());
    std::vector<std::size_t> fill(offsets_.begin(), offsets_.end() - 1);
    for (std::size_t f = 0; f < ranges.size(); ++f) {
        for (std::uint32_t p = ranges[f].first; p < ranges[f].last; ++p) {
            facets_[fill[p]++] = static_cast<std::uint32_t>(f);
        }
    }
}

}  // namespace mixengine
