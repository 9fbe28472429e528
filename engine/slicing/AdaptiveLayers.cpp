#include "slicing/AdaptiveLayers.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "common/Error.h"

namespace mixengine {
namespace {

/// layer_height + variation down to layer_height − variation by step, positive only.
std::vector<coord_um> allowedHeights(const AdaptiveLayerParams& p) {
    if (p.step_um <= 0)
        throw InputError("setting 'adaptive_layer_height_variation_step': must be positive, got " +
                         std::to_string(p.step_um) + " um");
    std::vector<coord_um> heights;
    for (coord_um h = p.layer_height_um + p.variation_um; h >= p.layer_height_um - p.variation_um && h > 0;
         h -= p.step_um)
        heights.push_back(h);
    if (heights.empty())
        throw InputError("setting 'adaptive_layer_height_variation': leaves no positive layer height");
    return heights;
}

/// The search for one layer's height above the current top.
class NextLayer {
  public:
    NextLayer(const std::vector<FaceSlope>& faces, const std::vector<coord_um>& heights,
              const AdaptiveLayerParams& params)
        : faces_(faces),
          heights_(heights),
          params_(params),
          smallest_(*std::min_element(heights.begin(), heights.end())) {}

    /// The height of the layer above `z` (the layer below is `previous` thick); 0 when no face is left.
    coord_um find(coord_um z, coord_um previous) {
        double flattest = std::numeric_limits<double>::max();
        coord_um flattest_height = 0;
        for (std::size_t k = 0; k < heights_.size(); ++k) {
            const coord_um h = heights_[k];
            narrow(z, z + (params_.middle ? h / 2 : h), k == 0);
            if (interest_.empty())
                return 0;
            double angle = std::numeric_limits<double>::max();
            for (std::size_t i : interest_)
                angle = std::min(angle, faces_[i].angle);
            if (angle < flattest)
                flattest = angle, flattest_height = h;
            const bool falls = previous > h && previous - h > params_.step_um;
            if (!falls && h - previous > params_.step_um && h > smallest_)
                continue;
            const double tangent = std::tan(angle);
            if (tangent == 0.0 || double(h) / tangent <= double(params_.threshold_um) || h == smallest_ ||
                falls)
                return h;
        }
        return flattest_height;
    }

  private:
    /// The faces meeting [lower, upper]; for the first height all faces are looked at, for the lower
    /// ones only those found before.
    void narrow(coord_um lower, coord_um upper, bool fresh) {
        std::vector<std::size_t> kept;
        if (fresh) {
            for (std::size_t i = 0; i < faces_.size(); ++i) {
                if (faces_[i].min_z <= upper && faces_[i].max_z >= lower)
                    kept.push_back(i);
            }
        } else {
            for (std::size_t i : interest_) {
                if (faces_[i].min_z <= upper)
                    kept.push_back(i);
            }
        }
        interest_ = std::move(kept);
    }

    const std::vector<FaceSlope>& faces_;
    const std::vector<coord_um>& heights_;
    const AdaptiveLayerParams& params_;
    coord_um smallest_;
    std::vector<std::size_t> interest_;
};

}  // namespace

std::vector<FaceSlope> faceSlopes(const Mesh& mesh) {
    std::vector<FaceSlope> slopes;
    slopes.reserve(mesh.faces.size());
    for (const Face& face : mesh.faces) {
        const Point3& a = mesh.vertices[face.v[0]];
        const Point3& b = mesh.vertices[face.v[1]];
        const Point3& c = mesh.vertices[face.v[2]];
        const Vec3 u{double(b.x - a.x), double(b.y - a.y), double(b.z - a.z)};
        const Vec3 v{double(c.x - a.x), double(c.y - a.y), double(c.z - a.z)};
        const Vec3 n = cross(u, v);
        const double size = length(n);
        double angle = size > 0 ? std::acos(std::min(1.0, std::abs(n.z) / size)) : std::numbers::pi;
        if (angle == 0.0)
            angle = std::numbers::pi;  // horizontal: never the flattest
        slopes.push_back({std::min({a.z, b.z, c.z}), std::max({a.z, b.z, c.z}), angle});
    }
    return slopes;
}

std::vector<LayerZ> adaptiveLayerHeights(const std::vector<FaceSlope>& faces,
                                         const AdaptiveLayerParams& params) {
    const std::vector<coord_um> heights = allowedHeights(params);
    std::vector<LayerZ> layers{{params.layer_height_0_um, 0, params.layer_height_0_um}};
    NextLayer next(faces, heights, params);
    coord_um previous = params.layer_height_0_um;
    while (true) {
        const coord_um z = layers.back().print_z;
        const coord_um h = next.find(z, previous);
        if (h <= 0)
            break;
        layers.push_back({z + h, z, z + h});
        previous = h;
    }
    return layers;
}

}  // namespace mixengine
